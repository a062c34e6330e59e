//! The cases of `tests/statements.rs`: each statement the diagnosis can make, drawn where it
//! shows (known mistakes by the project's variant renderer, fitted deviations by the student
//! caster of `examples/support/student.rs`), and the pictures a claim is measured on: theirs, the
//! exact ones, and what the exact rays hit, with a ray caster of this file's own for every
//! sphere a ray meets.
#![allow(dead_code)]

use glam::{DVec2, DVec3};
use image::RgbImage;
use raytracer::compare::{Mistake, MistakeSet};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Frame, View, render};
use raytracer::scene::{Scene, load_scene};

use super::compare_run;
use super::student::{self, DepthRule, Keep, NonSquare, OutsideRule, Program};

pub(crate) fn scene(relative: &str) -> Scene {
    load_scene(&compare_run::path(relative)).unwrap()
}

pub(crate) fn course(name: &str) -> Scene {
    scene(&format!("scenes/{name}.txt"))
}

/// How a case's images are drawn.
pub(crate) enum Drawn {
    /// By the variant renderer, with these known mistakes.
    Mistakes(MistakeSet),
    /// By the student caster.
    Student(Box<Program>),
}

/// One statement to draw and measure.
pub(crate) struct Case {
    /// The statement the images must draw out of the diagnosis.
    pub(crate) word: &'static str,
    pub(crate) scene: Scene,
    pub(crate) size_px: (u32, u32),
    /// The range their program draws depth over, and the diagnosis is given.
    pub(crate) range: (f64, f64),
    pub(crate) drawn: Drawn,
}

pub(crate) fn words(mistakes: &[Mistake]) -> Drawn {
    Drawn::Mistakes(MistakeSet::of(mistakes))
}

pub(crate) fn program(change: impl FnOnce(&mut Program)) -> Drawn {
    let mut program = Program::course();
    change(&mut program);
    Drawn::Student(Box::new(program))
}

pub(crate) fn case(
    word: &'static str,
    scene: Scene,
    size_px: (u32, u32),
    range: (f64, f64),
    drawn: Drawn,
) -> Case {
    Case {
        word,
        scene,
        size_px,
        range,
        drawn,
    }
}

/// Every statement the diagnosis can make, each drawn where it shows.
pub(crate) fn cases() -> Vec<Case> {
    use Mistake::*;
    let s01 = || course("scene1_01");
    let s02 = || course("scene1_02");
    let every = || scene(compare_run::SCENE);
    // One sphere off the centre on a grey background: where a map of the screen sends a disc.
    let off = || scene("tests/compare/off-centre.txt");
    // Spheres around and behind the camera's centre, one straddling it: what a tmin loses.
    let around = || scene("tests/compare/around-camera.txt");
    // One small sphere at the centre: room to move a whole strip within the image.
    let small = || scene("tests/compare/small.txt");
    vec![
        case(
            "pixel-corners",
            s01(),
            (200, 200),
            (9.0, 11.0),
            words(&[PixelCorners]),
        ),
        case(
            "no-square-root",
            s02(),
            (100, 100),
            (8.0, 12.0),
            words(&[NoSquareRoot]),
        ),
        case(
            "tmin-zero",
            around(),
            (100, 100),
            (-4.0, 4.0),
            words(&[TminZero]),
        ),
        case(
            "tmin-minus-one",
            around(),
            (100, 100),
            (-4.0, 4.0),
            words(&[TminMinusOne]),
        ),
        case(
            "far-root",
            s02(),
            (100, 100),
            (8.0, 12.0),
            words(&[FarRoot]),
        ),
        case(
            "stretched",
            s01(),
            (120, 80),
            (9.0, 11.0),
            words(&[Stretched]),
        ),
        case(
            "flipped-vertically",
            off(),
            (100, 100),
            (9.0, 11.0),
            words(&[FlippedVertically]),
        ),
        case(
            "depth-reversed",
            s02(),
            (100, 100),
            (9.0, 11.0),
            words(&[DepthReversed]),
        ),
        case(
            "depth-no-clamp",
            s02(),
            (100, 100),
            (9.0, 11.0),
            words(&[DepthNoClamp]),
        ),
        case(
            "depth-outside-black",
            s02(),
            (100, 100),
            (9.5, 11.0),
            words(&[DepthOutsideBlack]),
        ),
        case(
            "rounded",
            course("scene1_04"),
            (100, 100),
            (13.25, 15.75),
            words(&[Rounded]),
        ),
        case(
            "last-wins",
            every(),
            (120, 80),
            (6.0, 10.0),
            words(&[LastWins]),
        ),
        case(
            "mirrored",
            off(),
            (100, 100),
            (9.0, 11.0),
            words(&[Mirrored]),
        ),
        case("raw-up", every(), (120, 80), (6.0, 10.0), words(&[RawUp])),
        case(
            "unnormalized-direction",
            every(),
            (120, 80),
            (6.0, 10.0),
            words(&[UnnormalizedDirection]),
        ),
        case(
            "sample-offset",
            s01(),
            (200, 200),
            (9.0, 11.0),
            program(|p| p.sample = (0.3, 0.8)),
        ),
        case(
            "sample-offset",
            s01(),
            (200, 200),
            (9.0, 11.0),
            program(|p| p.sample = (3.5, -1.5)),
        ),
        case(
            "crop-not-centred",
            small(),
            (120, 80),
            (9.0, 11.0),
            program(|p| p.non_square = NonSquare::BottomStrip),
        ),
        case(
            "zoom",
            s01(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.axis_lengths = (1.25, 1.25)),
        ),
        case(
            "zoom",
            s01(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.axis_lengths = (0.8, 0.8)),
        ),
        case(
            "axes-scaled",
            s01(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.axis_lengths = (1.15, 0.85)),
        ),
        case(
            "swapped-axes",
            off(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.swapped = true),
        ),
        case(
            "axes",
            off(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.turn_degrees = 20.0),
        ),
        case(
            "t-ramp",
            s02(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.up_along_direction = 0.3),
        ),
        case(
            "no-depth-test",
            s02(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.keep = Keep::FirstInFile),
        ),
        case(
            "no-depth-test",
            s02(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.keep = Keep::LastInFile),
        ),
        case(
            "only-block",
            every(),
            (120, 80),
            (6.0, 10.0),
            program(|p| p.loops_to = Some((80, 80))),
        ),
        case(
            "sample-grid",
            s01(),
            (100, 100),
            (9.0, 11.0),
            program(|p| p.grid = Some((512, true))),
        ),
        case(
            "tmin",
            around(),
            (100, 100),
            (-4.0, 4.0),
            program(|p| p.tmin = -0.81),
        ),
        case(
            "near-root-only",
            around(),
            (100, 100),
            (-4.0, 4.0),
            program(|p| {
                p.tmin = -0.5;
                p.far_when_refused = false;
            }),
        ),
        case(
            "background",
            every(),
            (120, 80),
            (6.0, 10.0),
            program(|p| p.background = Some([10, 200, 30])),
        ),
        case(
            "background",
            every(),
            (120, 80),
            (6.0, 10.0),
            program(|p| p.background = Some([0, 0, 0])),
        ),
        case(
            "depth-range",
            every(),
            (120, 80),
            (6.5, 10.5),
            program(|p| p.depth = DepthRule::IntegerRange),
        ),
        case(
            "depth-per-image",
            every(),
            (120, 80),
            (6.0, 10.0),
            program(|p| {
                p.depth = DepthRule::PerImage {
                    near: 204.0,
                    far: 51.0,
                }
            }),
        ),
        case(
            "depth-quantity",
            course("scene1_04"),
            (100, 100),
            (0.0, 2.0),
            program(|p| p.depth = DepthRule::AbsZ),
        ),
        case(
            "depth-outside",
            every(),
            (120, 80),
            (6.0, 10.0),
            // A depth image filled with the background, written only within the range.
            program(|p| {
                p.outside = OutsideRule::Colour([51, 51, 51]);
                p.depth_no_hit_background = true;
            }),
        ),
        case(
            "depth-no-hit",
            every(),
            (120, 80),
            (6.0, 10.0),
            program(|p| p.depth_no_hit_background = true),
        ),
    ]
}

/// A case's pictures: theirs, the exact ones, and what the exact rays hit.
pub(crate) struct Pictures {
    pub(crate) scene: Scene,
    pub(crate) view: View,
    pub(crate) colour: RgbImage,
    pub(crate) depth: RgbImage,
    pub(crate) exact_colour: RgbImage,
    pub(crate) exact_depth: RgbImage,
    pub(crate) exact: Frame,
}

impl Case {
    pub(crate) fn pictures(&self) -> Pictures {
        let (width, height) = self.size_px;
        let range = DepthRange::new(self.range.0, self.range.1);
        let view = View::of_camera(&self.scene.camera, width, height, range);
        let (colour, depth) = match &self.drawn {
            Drawn::Mistakes(mistakes) => render_variant(&self.scene, &view, *mistakes),
            Drawn::Student(program) => student::render(
                program,
                &self.scene,
                width,
                height,
                self.range.0,
                self.range.1,
            ),
        };
        let exact = render(&self.scene, &view).unwrap();
        Pictures {
            scene: self.scene.clone(),
            view,
            exact_colour: exact.colour_image(),
            exact_depth: exact.depth_image(range),
            colour,
            depth,
            exact,
        }
    }
}

impl Pictures {
    /// The same pictures with theirs replaced by the exact ones: every claim must fail on them.
    pub(crate) fn exact_as_theirs(&self) -> Self {
        Self {
            scene: self.scene.clone(),
            view: self.view,
            colour: self.exact_colour.clone(),
            depth: self.exact_depth.clone(),
            exact_colour: self.exact_colour.clone(),
            exact_depth: self.exact_depth.clone(),
            exact: self.exact.clone(),
        }
    }

    pub(crate) fn size(&self) -> (u32, u32) {
        self.colour.dimensions()
    }

    /// The exact t at column `x`, row `row` (top row first).
    pub(crate) fn t(&self, x: u32, row: u32) -> f64 {
        self.exact.t[(row * self.exact.width_px + x) as usize]
    }

    /// Pixels (x, row) where the exact ray hits something.
    pub(crate) fn hit_pixels(&self) -> Vec<(u32, u32)> {
        let (w, h) = self.size();
        (0..h)
            .flat_map(|row| (0..w).map(move |x| (x, row)))
            .filter(|&(x, row)| self.t(x, row).is_finite())
            .collect()
    }

    /// Pixels (x, row) where the exact ray hits nothing.
    pub(crate) fn no_hit_pixels(&self) -> Vec<(u32, u32)> {
        let (w, h) = self.size();
        (0..h)
            .flat_map(|row| (0..w).map(move |x| (x, row)))
            .filter(|&(x, row)| !self.t(x, row).is_finite())
            .collect()
    }

    /// The scene's background as the course's bytes.
    pub(crate) fn scene_background(&self) -> [u8; 3] {
        self.scene
            .background
            .to_array()
            .map(|c| (f64::from(c) * 255.0).floor().clamp(0.0, 255.0) as u8)
    }

    /// The camera's unit direction, horizontal and screen up, and one pixel's side.
    pub(crate) fn basis(&self) -> (DVec3, DVec3, DVec3, f64) {
        let camera = &self.scene.camera;
        let d = camera.direction_world.normalize();
        let horizontal = d.cross(camera.up_world).normalize();
        let up = horizontal.cross(d);
        let (w, h) = self.size();
        (d, horizontal, up, camera.size_world / f64::from(w.max(h)))
    }

    /// The screen point (u, v) of the centre of pixel (x, row), world units.
    pub(crate) fn screen(&self, x: u32, row: u32) -> DVec2 {
        let (w, h) = self.size();
        let (.., pixel) = self.basis();
        let y_up = h - 1 - row;
        DVec2::new(
            (f64::from(x) + 0.5 - f64::from(w) / 2.0) * pixel,
            (f64::from(y_up) + 0.5 - f64::from(h) / 2.0) * pixel,
        )
    }

    /// Every sphere the exact ray of pixel (x, row) meets, in file order, with its near t: this
    /// file's own ray caster.
    pub(crate) fn all_hits(&self, x: u32, row: u32) -> Vec<(usize, f64)> {
        let (d, horizontal, up, _) = self.basis();
        let screen = self.screen(x, row);
        let origin = self.scene.camera.center_world + screen.x * horizontal + screen.y * up;
        self.scene
            .spheres
            .iter()
            .enumerate()
            .filter_map(|(index, sphere)| {
                let f = origin - sphere.center_world;
                let b = f.dot(d);
                let across = f - b * d;
                let inside = sphere.radius_world.powi(2) - across.length_squared();
                (inside >= 0.0).then(|| (index, -b - inside.sqrt()))
            })
            .collect()
    }

    /// The colour bytes of sphere `index`.
    pub(crate) fn sphere_bytes(&self, index: usize) -> [u8; 3] {
        let sphere = &self.scene.spheres[index];
        sphere
            .material
            .and_then(|m| self.scene.materials.get(m as usize))
            .map_or([1.0; 3], |m| m.diffuse_colour.to_array())
            .map(|c| (f64::from(c) * 255.0).floor().clamp(0.0, 255.0) as u8)
    }
}
