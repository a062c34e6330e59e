//! Every statement's sentence measured on pictures. A student acts on each sentence the diagnosis
//! prints, so each is a claim about their picture, tested like a figure: for every statement (a
//! known mistake or a fitted deviation) a case draws it — known mistakes with the project's
//! variant renderer (`oracle::mistaken`), fitted deviations with the student caster of
//! `examples/support/student.rs`, neither sharing code with the fit — has it diagnosed, reads the
//! claims its sentence makes (which way the picture moves and by how much, zoomed in or out, how
//! wide and tall a sphere is drawn, upside down or mirrored, near white or black, what colour
//! where nothing is hit, …) from the words themselves, and measures each on their picture beside
//! the exact one (centroids, second moments, flips, grey against t from a ray caster of this
//! file's own). Every measurement must also fail on the exact pictures, so none passes by
//! comparing nothing. The sentence is the one text the lines, the JSON, the viewer and the
//! grader give (`Deviation::explanation`); `a_statement_reads_the_same_in_the_lines_and_the_json`
//! checks that at the binary.

#[path = "common/compare_run.rs"]
mod compare_run;
#[path = "../examples/support/student.rs"]
mod student;

use glam::{DMat2, DVec2, DVec3};
use image::RgbImage;
use rayon::prelude::*;
use raytracer::compare::judge::judge;
use raytracer::compare::{Deviation, Mistake, MistakeSet, Theirs};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Frame, View, render};
use raytracer::scene::{Scene, load_scene, load_scene_from_bytes};

use student::{DepthRule, Keep, NonSquare, OutsideRule, Program};

/// One sphere off the centre on a grey background: where a map of the screen sends a disc.
const OFF_CENTRE: &str = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }
Background { color 0.3 0.3 0.3 }
Materials { numMaterials 1 PhongMaterial { diffuseColor 0.9 0.6 0.1 } }
Group { numObjects 1 MaterialIndex 0 Sphere { center 1 0.6 0 radius 0.7 } }";

/// One small sphere at the centre: room to move a whole strip without leaving the image.
const SMALL: &str = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }
Background { color 0 0 0 }
Materials { numMaterials 1 PhongMaterial { diffuseColor 0.2 0.5 1 } }
Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 0.4 } }";

/// Spheres around and behind the camera's centre, one of them straddling it, each of its own
/// colour: what a tmin loses.
const AROUND_CAMERA: &str = "OrthographicCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 size 6 }
Background { color 0.1 0.1 0.1 }
Materials { numMaterials 3
  PhongMaterial { diffuseColor 0.9 0.2 0.2 }
  PhongMaterial { diffuseColor 0.2 0.9 0.2 }
  PhongMaterial { diffuseColor 0.2 0.2 0.9 } }
Group { numObjects 3
  MaterialIndex 0 Sphere { center -1.2 0.8 0.3 radius 1 }
  MaterialIndex 1 Sphere { center 1.2 -0.5 3 radius 1.1 }
  MaterialIndex 2 Sphere { center 0.4 -1.5 -2.5 radius 0.9 } }";

fn course(name: &str) -> Scene {
    load_scene(&compare_run::path(&format!("scenes/{name}.txt"))).unwrap()
}

fn inline(name: &str, text: &str) -> Scene {
    load_scene_from_bytes(name, text.as_bytes()).unwrap()
}

/// How a case's images are drawn.
enum Drawn {
    /// By the variant renderer, with these known mistakes.
    Mistakes(MistakeSet),
    /// By the student caster.
    Student(Box<Program>),
}

/// One statement to draw and measure.
struct Case {
    /// The statement the images must draw out of the diagnosis.
    word: &'static str,
    scene: Scene,
    size_px: (u32, u32),
    /// The range their program draws depth over, and the diagnosis is given.
    range: (f64, f64),
    drawn: Drawn,
}

fn words(mistakes: &[Mistake]) -> Drawn {
    Drawn::Mistakes(MistakeSet::of(mistakes))
}

fn program(change: impl FnOnce(&mut Program)) -> Drawn {
    let mut program = Program::course();
    change(&mut program);
    Drawn::Student(Box::new(program))
}

fn case(
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
fn cases() -> Vec<Case> {
    use Mistake::*;
    let s01 = || course("scene1_01");
    let s02 = || course("scene1_02");
    let every = || load_scene(&compare_run::path(compare_run::SCENE)).unwrap();
    let off = || inline("off-centre", OFF_CENTRE);
    let around = || inline("around-camera", AROUND_CAMERA);
    let small = || inline("small", SMALL);
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
struct Pictures {
    scene: Scene,
    view: View,
    colour: RgbImage,
    depth: RgbImage,
    exact_colour: RgbImage,
    exact_depth: RgbImage,
    exact: Frame,
}

impl Case {
    fn pictures(&self) -> Pictures {
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
    fn exact_as_theirs(&self) -> Self {
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

    fn size(&self) -> (u32, u32) {
        self.colour.dimensions()
    }

    /// The exact t at column `x`, row `row` (top row first).
    fn t(&self, x: u32, row: u32) -> f64 {
        self.exact.t[(row * self.exact.width_px + x) as usize]
    }

    /// Pixels (x, row) where the exact ray hits something.
    fn hit_pixels(&self) -> Vec<(u32, u32)> {
        let (w, h) = self.size();
        (0..h)
            .flat_map(|row| (0..w).map(move |x| (x, row)))
            .filter(|&(x, row)| self.t(x, row).is_finite())
            .collect()
    }

    /// Pixels (x, row) where the exact ray hits nothing.
    fn no_hit_pixels(&self) -> Vec<(u32, u32)> {
        let (w, h) = self.size();
        (0..h)
            .flat_map(|row| (0..w).map(move |x| (x, row)))
            .filter(|&(x, row)| !self.t(x, row).is_finite())
            .collect()
    }

    /// The scene's background as the course's bytes.
    fn scene_background(&self) -> [u8; 3] {
        self.scene
            .background
            .to_array()
            .map(|c| (f64::from(c) * 255.0).floor().clamp(0.0, 255.0) as u8)
    }

    /// The camera's unit direction, horizontal and screen up, and one pixel's side.
    fn basis(&self) -> (DVec3, DVec3, DVec3, f64) {
        let camera = &self.scene.camera;
        let d = camera.direction_world.normalize();
        let horizontal = d.cross(camera.up_world).normalize();
        let up = horizontal.cross(d);
        let (w, h) = self.size();
        (d, horizontal, up, camera.size_world / f64::from(w.max(h)))
    }

    /// The screen point (u, v) of the centre of pixel (x, row), world units.
    fn screen(&self, x: u32, row: u32) -> DVec2 {
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
    fn all_hits(&self, x: u32, row: u32) -> Vec<(usize, f64)> {
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
    fn sphere_bytes(&self, index: usize) -> [u8; 3] {
        let sphere = &self.scene.spheres[index];
        sphere
            .material
            .and_then(|m| self.scene.materials.get(m as usize))
            .map_or([1.0; 3], |m| m.diffuse_colour.to_array())
            .map(|c| (f64::from(c) * 255.0).floor().clamp(0.0, 255.0) as u8)
    }
}

/// The lit pixels of an image (those unlike its top-left corner, the background in every case
/// that measures shapes): their count, centroid (x right, y up, pixels) and standard deviations.
fn shape(image: &RgbImage) -> (f64, DVec2, DVec2) {
    let corner = *image.get_pixel(0, 0);
    let (w, h) = image.dimensions();
    let mut points = Vec::new();
    for row in 0..h {
        for x in 0..w {
            if *image.get_pixel(x, row) != corner {
                points.push(DVec2::new(f64::from(x), f64::from(h - 1 - row)));
            }
        }
    }
    let n = points.len().max(1) as f64;
    let mean = points.iter().copied().sum::<DVec2>() / n;
    let var = points
        .iter()
        .map(|p| (*p - mean) * (*p - mean))
        .sum::<DVec2>()
        / n;
    (
        points.len() as f64,
        mean,
        DVec2::new(var.x.sqrt(), var.y.sqrt()),
    )
}

/// Pixels in which two images differ.
fn differing(a: &RgbImage, b: &RgbImage) -> usize {
    a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
}

fn flipped(image: &RgbImage) -> RgbImage {
    image::imageops::flip_vertical(image)
}

fn mirrored(image: &RgbImage) -> RgbImage {
    image::imageops::flip_horizontal(image)
}

/// The image transposed about its lower-left to upper-right diagonal: (x, y up) ↦ (y up, x).
fn transposed(image: &RgbImage) -> RgbImage {
    let (w, h) = image.dimensions();
    RgbImage::from_fn(h, w, |x, row| {
        let y_up = w - 1 - row;
        *image.get_pixel(y_up, h - 1 - x)
    })
}

/// A claim a sentence makes, as this file reads it from the words.
#[derive(Debug, Clone, PartialEq)]
enum Claim {
    /// The picture moves this many pixels right and up.
    Shifted {
        right: f64,
        up: f64,
    },
    /// Zoomed out (else in), each sphere this many times as wide.
    Zoomed {
        out: bool,
        width: Option<f64>,
    },
    /// Each sphere this many times as wide and as tall.
    Ellipse {
        wide: f64,
        tall: f64,
    },
    /// Circles drawn as ellipses longer along the image's longer side.
    LongerAlongLonger,
    UpsideDown,
    MirroredLeftRight,
    /// Mirrored across the diagonal from the lower left to the upper right.
    Transposed,
    /// A feature at exact pixel q is drawn at M⁻¹(q − c) + c (one pixel along x moves the first
    /// column of M, along y the second, in course pixels).
    Axes(DMat2),
    NearBlackFarWhite,
    /// Where no ray hits, the depth image is this colour.
    DepthNoHit([u8; 3]),
    /// These bytes are the scene's background colour.
    SceneBackground([u8; 3]),
    /// The colour image's background is the first, the scene's the second.
    Background([u8; 3], [u8; 3]),
    /// White at the first t, black at the second.
    Ramp {
        white: f64,
        black: f64,
    },
    /// The nearest and farthest hit and their greys.
    Extremes {
        near_t: f64,
        near_grey: f64,
        far_t: f64,
        far_grey: f64,
    },
    /// t grows by these per unit of the screen to the right and up.
    TRamp {
        right: f64,
        up: f64,
    },
    /// The first (else the last) sphere in the file that the ray hits is drawn.
    FileOrder {
        last: bool,
    },
    /// Only the lower-left block of these columns and rows is drawn.
    Block(u32, u32),
    /// What lies before this t is not drawn as the exact picture draws it.
    LostBefore(f64),
    /// Some values one level brighter, none otherwise.
    OneLevelBrighter,
    /// Every hit farther.
    Farther,
    /// Depth beyond the range striped (neither white nor black).
    Striped,
    /// What is nearer than DMIN is black.
    NearerThanMinBlack,
    /// On an exact tie the later sphere wins.
    LaterWinsTie,
    /// The picture's height divided by the length of up across the direction.
    VerticalByUp,
    /// Every t divided by the direction's length.
    DividedByDirection,
    /// The depth image maps |z| of each hit.
    MapsAbsZ,
    /// Depth outside the range drawn in this colour.
    OutsideColour([u8; 3]),
    /// The depth wrong where a sphere is hit (and right where none is).
    DepthWrongWhereHit,
}

fn number_at(words: &[&str], at: usize) -> Option<f64> {
    let word = words.get(at)?;
    word.trim_matches(|c: char| !(c.is_ascii_digit() || c == '-' || c == '.'))
        .parse()
        .ok()
}

fn bytes_at(words: &[&str], at: usize) -> Option<[u8; 3]> {
    if words.get(at).is_some_and(|w| w.starts_with("black")) {
        return Some([0; 3]);
    }
    let byte = |i: usize| number_at(words, at + i).map(|v| v as u8);
    Some([byte(0)?, byte(1)?, byte(2)?])
}

/// The words after `phrase` in `sentence`, split on spaces.
fn after<'a>(sentence: &'a str, phrase: &str) -> Option<Vec<&'a str>> {
    sentence
        .find(phrase)
        .map(|at| sentence[at + phrase.len()..].split_whitespace().collect())
}

/// The claims a sentence makes, read from its words.
fn claims_of(sentence: &str) -> Vec<Claim> {
    let mut claims = Vec::new();
    if let Some(words) = after(sentence, "shifted ") {
        let (mut right, mut up) = (0.0, 0.0);
        let mut at = 0;
        loop {
            let (amount, direction) = if words.get(at) == Some(&"half") {
                (0.5, words.get(at + 3))
            } else if let Some(amount) = number_at(&words, at) {
                (amount, words.get(at + 2))
            } else {
                break;
            };
            let step = if words.get(at) == Some(&"half") { 4 } else { 3 };
            match direction.map(|d| d.trim_end_matches([',', ':', ';'])) {
                Some("right") => right += amount,
                Some("left") => right -= amount,
                Some("up") => up += amount,
                Some("down") => up -= amount,
                other => panic!("a shift without a direction: {other:?} in {sentence}"),
            }
            // "… right and up": a second direction with the same amount.
            if words.get(at + step) == Some(&"and")
                && let Some(second) = words.get(at + step + 1)
                && ["up", "down", "up:", "down:"].contains(second)
            {
                match second.trim_end_matches(':') {
                    "up" => up += amount,
                    _ => up -= amount,
                }
                break;
            }
            if words.get(at + step) != Some(&"and") {
                break;
            }
            at += step + 1;
        }
        claims.push(Claim::Shifted { right, up });
    }
    if sentence.contains("zoomed out") || sentence.contains("zoomed in") {
        let width = after(sentence, "each sphere ")
            .and_then(|w| number_at(&w, 0))
            .filter(|_| sentence.contains("× as wide)"));
        claims.push(Claim::Zoomed {
            out: sentence.contains("zoomed out"),
            width,
        });
    }
    if let Some(words) = after(sentence, "is drawn ")
        && words.get(1) == Some(&"as")
        && words.get(2) == Some(&"wide")
    {
        claims.push(Claim::Ellipse {
            wide: number_at(&words, 0).unwrap(),
            tall: number_at(&words, 4).unwrap(),
        });
    }
    if sentence.contains("longer along the image's longer side") {
        claims.push(Claim::LongerAlongLonger);
    }
    if sentence.contains("upside down") {
        claims.push(Claim::UpsideDown);
    }
    if sentence.contains("mirrored left to right") {
        claims.push(Claim::MirroredLeftRight);
    }
    if sentence.contains("mirrored across its diagonal from the lower left to the upper right") {
        claims.push(Claim::Transposed);
    }
    if let Some(words) = after(sentence, "one pixel along x moves ") {
        let v = |i| number_at(&words, i).unwrap();
        // "(a, b), along y (c, d) course pixels"
        claims.push(Claim::Axes(DMat2::from_cols(
            DVec2::new(v(0), v(1)),
            DVec2::new(v(4), v(5)),
        )));
    }
    if sentence.contains("near is black and far is white") {
        claims.push(Claim::NearBlackFarWhite);
    }
    if let Some(words) = after(sentence, "where no ray hits, the depth image is ") {
        claims.push(Claim::DepthNoHit(bytes_at(&words, 0).unwrap()));
        if sentence.contains("your scene's background colour") {
            claims.push(Claim::SceneBackground(bytes_at(&words, 0).unwrap()));
        }
    }
    if let Some(words) = after(sentence, "the background is ") {
        let theirs = bytes_at(&words, 0).unwrap();
        let scene_at = words.iter().position(|w| *w == "says").unwrap() + 1;
        claims.push(Claim::Background(
            theirs,
            bytes_at(&words, scene_at).unwrap(),
        ));
    }
    if let Some(words) = after(sentence, "white at t = ") {
        let black_at = words.iter().position(|w| *w == "black").unwrap();
        let black_word = if words[black_at + 2] == "t" {
            black_at + 4
        } else {
            black_at + 2
        };
        claims.push(Claim::Ramp {
            white: number_at(&words, 0).unwrap(),
            black: number_at(&words, black_word).unwrap(),
        });
    }
    if let Some(words) = after(sentence, "the depth ramp runs from t = ") {
        // "a (grey g1) to t = b (grey g2)"
        claims.push(Claim::Extremes {
            near_t: number_at(&words, 0).unwrap(),
            near_grey: number_at(&words, 2).unwrap(),
            far_t: number_at(&words, 6).unwrap(),
            far_grey: number_at(&words, 8).unwrap(),
        });
    }
    if let Some(words) = after(sentence, "t grows by ") {
        let up_at = words.iter().position(|w| *w == "and").unwrap() + 1;
        claims.push(Claim::TRamp {
            right: number_at(&words, 0).unwrap(),
            up: number_at(&words, up_at).unwrap(),
        });
    }
    if sentence.contains("the first sphere in the file that the ray hits is drawn, nearer or not") {
        claims.push(Claim::FileOrder { last: false });
    }
    if sentence.contains("the last one hit wins, nearer or not") {
        claims.push(Claim::FileOrder { last: true });
    }
    if let Some(words) = after(sentence, "only the lower-left ") {
        let (w, h) = words[0].split_once('×').unwrap();
        claims.push(Claim::Block(w.parse().unwrap(), h.parse().unwrap()));
    }
    if let Some(words) = after(sentence, "whose near root lies before t = ") {
        claims.push(Claim::LostBefore(number_at(&words, 0).unwrap()));
    }
    if sentence.contains("near root lies more than 1 behind the camera centre is lost") {
        claims.push(Claim::LostBefore(-1.0));
    }
    if sentence.contains("what lies behind the camera centre is lost") {
        claims.push(Claim::LostBefore(0.0));
    }
    if sentence.contains("some are one level brighter") {
        claims.push(Claim::OneLevelBrighter);
    }
    if sentence.contains("every hit is farther than it should be") {
        claims.push(Claim::Farther);
    }
    if sentence.contains("is striped") {
        claims.push(Claim::Striped);
    }
    if sentence.contains("nearer than DMIN is black") {
        claims.push(Claim::NearerThanMinBlack);
    }
    if sentence.contains("on an exact tie of t the later sphere wins") {
        claims.push(Claim::LaterWinsTie);
    }
    if sentence.contains("height is divided by the length of up across the direction") {
        claims.push(Claim::VerticalByUp);
    }
    if sentence.contains("every t is divided by the direction's length") {
        claims.push(Claim::DividedByDirection);
    }
    if sentence.contains("maps |z| of each hit") {
        claims.push(Claim::MapsAbsZ);
    }
    if let Some(words) = after(sentence, "depth outside the range is drawn ")
        && number_at(&words, 0).is_some()
    {
        claims.push(Claim::OutsideColour(bytes_at(&words, 0).unwrap()));
    }
    if sentence.contains("the depth is wrong where a sphere is hit") {
        claims.push(Claim::DepthWrongWhereHit);
    }
    claims
}

fn near(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

/// The share of `pixels` for which `holds` is true (0 with no pixels).
fn share(pixels: &[(u32, u32)], holds: impl Fn(u32, u32) -> bool) -> f64 {
    if pixels.is_empty() {
        return 0.0;
    }
    pixels.iter().filter(|&&(x, row)| holds(x, row)).count() as f64 / pixels.len() as f64
}

fn grey(image: &RgbImage, x: u32, row: u32) -> f64 {
    f64::from(image.get_pixel(x, row).0[0])
}

/// The course's depth grey of `t` over white `white` … black `black`.
fn course_grey(t: f64, white: f64, black: f64) -> f64 {
    (255.0 * (black - t) / (black - white))
        .floor()
        .clamp(0.0, 255.0)
}

/// Measures `claim` on `p`: Ok when the picture shows it.
fn measure(claim: &Claim, p: &Pictures) -> Result<(), String> {
    let check = |ok: bool, what: String| if ok { Ok(()) } else { Err(what) };
    let (min_t, max_t) = (p.view.depth_range.min_t, p.view.depth_range.max_t);
    match *claim {
        Claim::Shifted { right, up } => {
            let (_, theirs, _) = shape(&p.colour);
            let (_, exact, _) = shape(&p.exact_colour);
            let moved = theirs - exact;
            check(
                near(moved.x, right, 0.04) && near(moved.y, up, 0.04),
                format!("moved {moved:?}, said right {right} up {up}"),
            )
        }
        Claim::Zoomed { out, width } => {
            let (area, ..) = shape(&p.colour);
            let (exact_area, ..) = shape(&p.exact_colour);
            let ratio = (area / exact_area).sqrt();
            check(
                (ratio < 0.98) == out
                    && (ratio > 1.02) != out
                    && width.is_none_or(|w| near(ratio, w, 0.02 * w)),
                format!("spheres {ratio}× as wide, said out {out}, {width:?}"),
            )
        }
        Claim::Ellipse { wide, tall } => {
            let (_, _, spread) = shape(&p.colour);
            let (_, _, exact) = shape(&p.exact_colour);
            let ratio = spread / exact;
            check(
                near(ratio.x, wide, 0.02 * wide) && near(ratio.y, tall, 0.02 * tall),
                format!("drawn {ratio:?} as wide and tall, said {wide} {tall}"),
            )
        }
        Claim::LongerAlongLonger => {
            let (w, h) = p.size();
            let (_, _, spread) = shape(&p.colour);
            let longer = if w > h {
                spread.x / spread.y
            } else {
                spread.y / spread.x
            };
            check(longer > 1.05, format!("longer side over shorter {longer}"))
        }
        Claim::UpsideDown => check_like(p, &flipped(&p.exact_colour), &flipped(&p.exact_depth)),
        Claim::MirroredLeftRight => {
            check_like(p, &mirrored(&p.exact_colour), &mirrored(&p.exact_depth))
        }
        Claim::Transposed => {
            check_like(p, &transposed(&p.exact_colour), &transposed(&p.exact_depth))
        }
        Claim::Axes(m) => {
            let (w, h) = p.size();
            // Pixel indices: the image's centre is at (W − 1)/2, (H − 1)/2.
            let centre = (DVec2::new(f64::from(w), f64::from(h)) - 1.0) / 2.0;
            let (_, theirs, _) = shape(&p.colour);
            let (_, exact, _) = shape(&p.exact_colour);
            let expected = m.inverse() * (exact - centre) + centre;
            check(
                (theirs - expected).length() <= 0.15,
                format!("disc at {theirs:?}, the axes said put it at {expected:?}"),
            )
        }
        Claim::NearBlackFarWhite => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, row)| (min_t..max_t).contains(&p.t(x, row)))
                .collect();
            let n = pixels.len() as f64;
            let mean_t = pixels.iter().map(|&(x, r)| p.t(x, r)).sum::<f64>() / n;
            let mean_g = pixels
                .iter()
                .map(|&(x, r)| grey(&p.depth, x, r))
                .sum::<f64>()
                / n;
            let covariance: f64 = pixels
                .iter()
                .map(|&(x, r)| (p.t(x, r) - mean_t) * (grey(&p.depth, x, r) - mean_g))
                .sum();
            check(
                covariance > 0.0 && n > 100.0,
                format!("grey against t: {covariance} over {n} px"),
            )
        }
        Claim::DepthNoHit(bytes) => {
            let pixels = p.no_hit_pixels();
            let held = share(&pixels, |x, row| p.depth.get_pixel(x, row).0 == bytes);
            check(
                held >= 0.99,
                format!("{held} of the no-hit pixels are {bytes:?}"),
            )
        }
        Claim::SceneBackground(bytes) => check(
            p.scene_background() == bytes,
            format!("the scene's background is {:?}", p.scene_background()),
        ),
        Claim::Background(theirs, scene) => {
            let pixels = p.no_hit_pixels();
            let held = share(&pixels, |x, row| p.colour.get_pixel(x, row).0 == theirs);
            check(
                held >= 0.99 && p.scene_background() == scene,
                format!(
                    "{held} of the no-hit pixels are {theirs:?}; scene {:?}",
                    p.scene_background()
                ),
            )
        }
        Claim::Ramp { white, black } => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, row)| {
                    let t = p.t(x, row);
                    t > white.min(black) && t < white.max(black)
                })
                .collect();
            let held = share(&pixels, |x, row| {
                near(
                    grey(&p.depth, x, row),
                    course_grey(p.t(x, row), white, black),
                    1.0,
                )
            });
            check(
                held >= 0.99 && pixels.len() > 50,
                format!(
                    "{held} of {} pixels drawn white at {white}, black at {black}",
                    pixels.len()
                ),
            )
        }
        Claim::Extremes {
            near_t,
            near_grey,
            far_t,
            far_grey,
        } => {
            let pixels = p.hit_pixels();
            let at = |pick: fn(f64, f64) -> bool| {
                let mut best = pixels[0];
                for &(x, row) in &pixels {
                    if pick(p.t(x, row), p.t(best.0, best.1)) {
                        best = (x, row);
                    }
                }
                (p.t(best.0, best.1), grey(&p.depth, best.0, best.1))
            };
            let (t0, g0) = at(|a, b| a < b);
            let (t1, g1) = at(|a, b| a > b);
            check(
                near(t0, near_t, 1e-3 * near_t.abs().max(1.0))
                    && near(g0, near_grey, 1.0)
                    && near(t1, far_t, 1e-3 * far_t.abs().max(1.0))
                    && near(g1, far_grey, 1.0),
                format!("nearest t {t0} grey {g0}, farthest t {t1} grey {g1}"),
            )
        }
        Claim::TRamp { right, up } => {
            // Their t from their grey (the middle of its level) less the exact t, fitted as
            // a·u + b·v + c by least squares.
            let width = max_t - min_t;
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| (1.0..254.0).contains(&grey(&p.depth, x, r)))
                .collect();
            let rows: Vec<([f64; 3], f64)> = pixels
                .iter()
                .map(|&(x, r)| {
                    let theirs = max_t - (grey(&p.depth, x, r) + 0.5) / 255.0 * width;
                    let s = p.screen(x, r);
                    ([s.x, s.y, 1.0], theirs - p.t(x, r))
                })
                .collect();
            let [a, b, _] = least_squares(&rows);
            let slack = |said: f64| 0.05 + 0.1 * said.abs();
            check(
                pixels.len() > 100 && near(a, right, slack(right)) && near(b, up, slack(up)),
                format!("t grows {a} right, {b} up over {} px", pixels.len()),
            )
        }
        Claim::FileOrder { last } => {
            let (w, h) = p.size();
            let mut telling = 0;
            let mut held = 0;
            for row in 0..h {
                for x in 0..w {
                    let hits = p.all_hits(x, row);
                    if hits.len() < 2 {
                        continue;
                    }
                    let in_order = if last { hits[hits.len() - 1] } else { hits[0] };
                    let nearest = hits
                        .iter()
                        .copied()
                        .fold(hits[0], |a, b| if b.1 < a.1 { b } else { a });
                    if p.sphere_bytes(in_order.0) == p.sphere_bytes(nearest.0) {
                        continue;
                    }
                    telling += 1;
                    held += usize::from(p.colour.get_pixel(x, row).0 == p.sphere_bytes(in_order.0));
                }
            }
            check(
                telling >= 20 && held as f64 >= 0.99 * f64::from(telling),
                format!("{held} of {telling} telling pixels show the sphere in file order"),
            )
        }
        Claim::Block(columns, rows) => {
            let (w, h) = p.size();
            let background = p.scene_background();
            let mut outside_ok = true;
            let mut inside_lit = 0;
            for row in 0..h {
                for x in 0..w {
                    let y_up = h - 1 - row;
                    let colour = p.colour.get_pixel(x, row).0;
                    if x >= columns || y_up >= rows {
                        outside_ok &= colour == background;
                    } else {
                        inside_lit += usize::from(colour != background);
                    }
                }
            }
            let exact_outside = (0..h).any(|row| {
                (0..w).any(|x| {
                    (x >= columns || h - 1 - row >= rows)
                        && p.exact_colour.get_pixel(x, row).0 != background
                })
            });
            check(
                outside_ok && inside_lit > 0 && exact_outside,
                format!("outside the block background: {outside_ok}, inside lit {inside_lit}"),
            )
        }
        Claim::LostBefore(t) => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| p.t(x, r) < t)
                .collect();
            let lost = share(&pixels, |x, r| {
                p.colour.get_pixel(x, r) != p.exact_colour.get_pixel(x, r)
                    || p.depth.get_pixel(x, r) != p.exact_depth.get_pixel(x, r)
            });
            let kept = share(&p.hit_pixels(), |x, r| {
                p.t(x, r) >= t && p.colour.get_pixel(x, r) == p.exact_colour.get_pixel(x, r)
            });
            check(
                pixels.len() >= 20 && lost >= 0.95 && kept > 0.0,
                format!("{lost} of {} pixels before t = {t} lost", pixels.len()),
            )
        }
        Claim::OneLevelBrighter => {
            let mut brighter = 0;
            let mut other = 0;
            for (a, b) in p.colour.pixels().zip(p.exact_colour.pixels()) {
                for (&theirs, &exact) in a.0.iter().zip(&b.0) {
                    match i16::from(theirs) - i16::from(exact) {
                        0 => {}
                        1 => brighter += 1,
                        _ => other += 1,
                    }
                }
            }
            check(
                brighter > 0 && other == 0,
                format!("{brighter} one brighter, {other} otherwise"),
            )
        }
        Claim::Farther => {
            let pixels = p.hit_pixels();
            let never_nearer = pixels
                .iter()
                .all(|&(x, r)| grey(&p.depth, x, r) <= grey(&p.exact_depth, x, r));
            let farther = share(&pixels, |x, r| {
                grey(&p.depth, x, r) < grey(&p.exact_depth, x, r)
            });
            check(
                never_nearer && farther >= 0.5,
                format!("nearer nowhere: {never_nearer}, farther {farther}"),
            )
        }
        Claim::Striped => {
            let beyond = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| !(min_t..=max_t).contains(&p.t(x, r)))
                .filter(|&(x, r)| !matches!(grey(&p.depth, x, r) as u8, 0 | 255))
                .count();
            check(
                beyond >= 20,
                format!("{beyond} pixels beyond the range neither white nor black"),
            )
        }
        Claim::NearerThanMinBlack => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| p.t(x, r) < min_t)
                .collect();
            let black = share(&pixels, |x, r| grey(&p.depth, x, r) == 0.0);
            check(
                pixels.len() >= 20 && black >= 0.99,
                format!("{black} of {} black", pixels.len()),
            )
        }
        Claim::LaterWinsTie => {
            let (w, h) = p.size();
            let (mut ties, mut later) = (0, 0);
            for row in 0..h {
                for x in 0..w {
                    let hits = p.all_hits(x, row);
                    let nearest = hits.iter().map(|h| h.1).fold(f64::INFINITY, f64::min);
                    let tied: Vec<usize> = hits
                        .iter()
                        .filter(|h| h.1 == nearest)
                        .map(|h| h.0)
                        .collect();
                    if tied.len() < 2
                        || p.sphere_bytes(tied[0]) == p.sphere_bytes(tied[tied.len() - 1])
                    {
                        continue;
                    }
                    ties += 1;
                    later += usize::from(
                        p.colour.get_pixel(x, row).0 == p.sphere_bytes(tied[tied.len() - 1]),
                    );
                }
            }
            check(
                ties >= 20 && later == ties,
                format!("{later} of {ties} tied pixels show the later sphere"),
            )
        }
        Claim::VerticalByUp => {
            let camera = &p.scene.camera;
            let d = camera.direction_world.normalize();
            let across = (camera.up_world - camera.up_world.dot(d) * d).length();
            let (_, _, spread) = shape(&p.colour);
            let (_, _, exact) = shape(&p.exact_colour);
            let ratio = spread.y / exact.y;
            check(
                near(ratio, 1.0 / across, 0.03) && !near(across, 1.0, 0.02),
                format!("{ratio}× as tall, up across the direction {across}"),
            )
        }
        Claim::DividedByDirection => {
            let length = p.scene.camera.direction_world.length();
            let pixels = p.hit_pixels();
            let held = share(&pixels, |x, r| {
                near(
                    grey(&p.depth, x, r),
                    course_grey(p.t(x, r) / length, min_t, max_t),
                    1.0,
                )
            });
            check(
                held >= 0.99 && length != 1.0,
                format!("{held} drawn from t/|direction|"),
            )
        }
        Claim::MapsAbsZ => {
            let (d, horizontal, up, _) = p.basis();
            let pixels = p.hit_pixels();
            let held = share(&pixels, |x, r| {
                let s = p.screen(x, r);
                let hit = p.scene.camera.center_world + s.x * horizontal + s.y * up + p.t(x, r) * d;
                near(
                    grey(&p.depth, x, r),
                    course_grey(hit.z.abs(), min_t, max_t),
                    1.0,
                )
            });
            check(held >= 0.99, format!("{held} drawn from |z|"))
        }
        Claim::OutsideColour(bytes) => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| !(min_t..=max_t).contains(&p.t(x, r)))
                .collect();
            let held = share(&pixels, |x, r| p.depth.get_pixel(x, r).0 == bytes);
            check(
                pixels.len() >= 20 && held >= 0.99,
                format!("{held} of {} outside are {bytes:?}", pixels.len()),
            )
        }
        Claim::DepthWrongWhereHit => {
            let wrong = share(&p.hit_pixels(), |x, r| {
                p.depth.get_pixel(x, r) != p.exact_depth.get_pixel(x, r)
            });
            let right = share(&p.no_hit_pixels(), |x, r| {
                p.depth.get_pixel(x, r) == p.exact_depth.get_pixel(x, r)
            });
            check(
                wrong >= 0.5 && right >= 0.99,
                format!("wrong at {wrong} of the hits, right at {right} of the rest"),
            )
        }
    }
}

/// Whether their pictures are `colour` and `depth` (a flip or mirror of the exact ones) to
/// within a few pixels, and not the exact ones.
fn check_like(p: &Pictures, colour: &RgbImage, depth: &RgbImage) -> Result<(), String> {
    let (w, h) = p.size();
    let allowed = (w * h / 200) as usize;
    let off = differing(&p.colour, colour) + differing(&p.depth, depth);
    let from_exact = differing(&p.colour, &p.exact_colour) + differing(&p.depth, &p.exact_depth);
    if off <= allowed && from_exact > 10 * allowed.max(1) {
        Ok(())
    } else {
        Err(format!(
            "{off} pixels off the picture said, {from_exact} off the exact one"
        ))
    }
}

/// The least-squares solution x of rows (a, b): a·x ≈ b, three unknowns (the normal equations).
fn least_squares(rows: &[([f64; 3], f64)]) -> [f64; 3] {
    let mut normal = glam::DMat3::ZERO;
    let mut right = DVec3::ZERO;
    for (a, b) in rows {
        let a = DVec3::from_array(*a);
        normal += glam::DMat3::from_cols(a * a.x, a * a.y, a * a.z);
        right += a * *b;
    }
    (normal.inverse() * right).to_array()
}

/// The statements an answer makes, in full, in part or as alternatives.
fn every_statement(answer: &raytracer::compare::Diagnosis) -> Vec<Deviation> {
    let mut all: Vec<Deviation> = answer.stated().to_vec();
    all.extend_from_slice(answer.partial());
    for set in answer.alternatives() {
        all.extend_from_slice(set);
    }
    all
}

#[test]
fn every_statement_s_claims_hold_on_the_picture_it_is_said_of() {
    let cases = cases();
    let failures: Vec<String> = cases
        .par_iter()
        .map(|case| {
            let p = case.pictures();
            let range = Some(p.view.depth_range);
            let judged = judge(
                &p.scene,
                &p.exact,
                Theirs {
                    colour: Some(&p.colour),
                    depth: Some(&p.depth),
                },
                range,
            )
            .unwrap();
            let said = every_statement(&judged.diagnosis);
            let Some(statement) = said.iter().find(|s| s.word() == case.word) else {
                return vec![format!(
                    "{}: not said; the answer: {:?}",
                    case.word,
                    said.iter()
                        .map(Deviation::name_and_values)
                        .collect::<Vec<_>>()
                )];
            };
            let sentence = statement.explanation();
            let claims = claims_of(&sentence);
            let mut failures = Vec::new();
            if claims.is_empty() {
                failures.push(format!("{}: no claim read from \"{sentence}\"", case.word));
            }
            let exact = p.exact_as_theirs();
            for claim in &claims {
                if let Err(why) = measure(claim, &p) {
                    failures.push(format!(
                        "{} ({}): {claim:?} does not hold: {why}\n  \"{sentence}\"",
                        case.word,
                        statement.name_and_values()
                    ));
                }
                if !matches!(claim, Claim::SceneBackground(_)) && measure(claim, &exact).is_ok() {
                    failures.push(format!(
                        "{}: {claim:?} also holds on the exact pictures: it measures nothing",
                        case.word
                    ));
                }
            }
            failures
        })
        .flatten()
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The claim reader on sentences whose claims are known: a sentence that points the other way
/// reads the other way.
#[test]
fn the_claim_reader_reads_directions_amounts_and_colours() {
    assert_eq!(
        claims_of("so the picture is shifted half a pixel right and up: add ½"),
        [Claim::Shifted {
            right: 0.5,
            up: 0.5
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted half a pixel left and down: add ½"),
        [Claim::Shifted {
            right: -0.5,
            up: -0.5
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted 0.2 pixels right and 0.3 pixels down: give"),
        [Claim::Shifted {
            right: 0.2,
            up: -0.3
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted 1 pixel up: give"),
        [Claim::Shifted {
            right: 0.0,
            up: 1.0
        }]
    );
    assert_eq!(
        claims_of(
            "where no ray hits, the depth image is 76 76 76, your scene's background colour, instead"
        ),
        [Claim::DepthNoHit([76; 3]), Claim::SceneBackground([76; 3])]
    );
}

/// The sentence is one text: the lines print it after the statement's name and values, the JSON
/// gives it as the statement's `text`, and both are the library's `explanation`.
#[test]
fn a_statement_reads_the_same_in_the_lines_and_the_json() {
    let folder = tempfile::tempdir().unwrap();
    compare_run::write_mistaken(
        folder.path(),
        MistakeSet::of(&[Mistake::PixelCorners, Mistake::DepthReversed]),
        "png",
    );
    let lines = compare_run::stdout(&compare_run::compare(folder.path(), "png", &[]));
    let json = compare_run::compare(folder.path(), "png", &["-compare_format", "json"]);
    let answer: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let statements = answer["statements"].as_array().unwrap();
    assert_eq!(statements.len(), 2, "{lines}");
    for (statement, mistake) in statements
        .iter()
        .zip([Mistake::PixelCorners, Mistake::DepthReversed])
    {
        let text = statement["text"].as_str().unwrap();
        assert_eq!(text, Deviation::Word(mistake).explanation());
        assert!(
            lines.contains(&format!("diagnosis: {}: {text}\n", mistake.word())),
            "{lines}"
        );
    }
}

/// Every statement the answer can make has a case above: the fifteen known mistakes, and each
/// name of docs/compare-json.md's table of fitted statements.
#[test]
fn every_statement_has_a_case() {
    let table = std::fs::read_to_string(compare_run::path("docs/compare-json.md")).unwrap();
    let section = table
        .split("## The statements and their values")
        .nth(1)
        .unwrap();
    let mut names: Vec<String> = section
        .lines()
        .filter_map(|line| line.strip_prefix("| `"))
        .filter_map(|rest| rest.split('`').next())
        .map(str::to_owned)
        .collect();
    assert!(names.len() >= 16, "{names:?}");
    names.extend(Mistake::ALL.iter().map(|m| m.word().to_owned()));
    let covered: Vec<&str> = cases().iter().map(|c| c.word).collect();
    let missing: Vec<&String> = names
        .iter()
        .filter(|name| !covered.contains(&name.as_str()))
        .collect();
    assert!(missing.is_empty(), "statements without a case: {missing:?}");
}
