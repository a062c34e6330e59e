//! A student's ray caster with knobs: the generated corpus of the diagnosis. It is written as a
//! student writes the assignment — a camera that builds its own horizontal and up vectors, one
//! world-space ray per pixel, the textbook quadratic against every sphere, a loop that keeps a
//! hit — and shares no code with the diagnosis's model renderer (`raytracer::compare`), so that a
//! fit is never checked against itself. Each knob is a way real programs differ; a seeded draw
//! picks one to three of them with values that are not round, and says what it picked (the
//! truth the diagnosis is judged against).

#![allow(dead_code)]

#[path = "student_draw.rs"]
mod draw;

use image::{Rgb, RgbImage};
use raytracer::scene::Scene;

#[allow(unused_imports)] // not every file that includes the caster draws programs
pub(crate) use draw::{Draw, draw_program};

/// Which hit the program keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Keep {
    Nearest,
    FirstInFile,
    LastInFile,
}

/// How a non-square image sits on the camera's square.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum NonSquare {
    /// The course's: a centred crop.
    Centred,
    /// Each axis over the whole square.
    Stretched,
    /// The width used for both axes, measured from the square's lower edge.
    BottomStrip,
    /// Loops to min(W, H): only that block is drawn.
    Block,
}

/// How the depth image is made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum DepthRule {
    /// The course's `(DMAX − t)/(DMAX − DMIN)`.
    Range,
    /// Near black.
    Reversed,
    /// From the nearest (grey `near`) to the farthest hit (grey `far`) of this image.
    PerImage { near: f64, far: f64 },
    /// |z| of the hit point over the range.
    AbsZ,
    /// The range read as whole numbers.
    IntegerRange,
}

/// What depth outside the range becomes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum OutsideRule {
    Clamp,
    Wrap,
    Black,
    /// Drawn in a colour of its own.
    Colour([u8; 3]),
}

/// A student's program: every knob at the course's value is the course's program.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Program {
    /// Where in the pixel the ray passes (the course's: 0.5 0.5).
    pub(crate) sample: (f64, f64),
    /// Lengths of the horizontal and up vectors (the course's: 1 1).
    pub(crate) axis_lengths: (f64, f64),
    /// How much of the direction the up vector keeps (the course's: 0, made perpendicular).
    pub(crate) up_along_direction: f64,
    /// The screen's horizontal and up turned about the direction by this many degrees
    /// (counter-clockwise as seen along the direction; the course's: 0).
    pub(crate) turn_degrees: f64,
    /// `up × direction` for the horizontal.
    pub(crate) mirrored: bool,
    /// Rows written top row first.
    pub(crate) upside_down: bool,
    /// x samples the screen's v and y its u.
    pub(crate) swapped: bool,
    pub(crate) non_square: NonSquare,
    /// Samples on a grid of this many a side over the screen, each written to the pixel it falls
    /// in, the last (true) or first that hits setting the pixel (`None`: one ray per pixel).
    pub(crate) grid: Option<(u32, bool)>,
    /// The pixel loops stop at these columns and rows (the rest keeps the background), the
    /// mapping unchanged (`None`: the whole image).
    pub(crate) loops_to: Option<(u32, u32)>,
    pub(crate) keep: Keep,
    /// Hits below tmin are refused (the course's: −∞).
    pub(crate) tmin: f64,
    /// The far root is tried when the near one is refused.
    pub(crate) far_when_refused: bool,
    /// The background as bytes (`None`: the scene's).
    pub(crate) background: Option<[u8; 3]>,
    /// Bytes rounded.
    pub(crate) rounded: bool,
    pub(crate) depth: DepthRule,
    pub(crate) outside: OutsideRule,
    /// The depth image's no-hit colour is the background.
    pub(crate) depth_no_hit_background: bool,
}

impl Program {
    /// The course's program.
    pub(crate) fn course() -> Self {
        Self {
            sample: (0.5, 0.5),
            axis_lengths: (1.0, 1.0),
            up_along_direction: 0.0,
            turn_degrees: 0.0,
            mirrored: false,
            upside_down: false,
            swapped: false,
            non_square: NonSquare::Centred,
            grid: None,
            loops_to: None,
            keep: Keep::Nearest,
            tmin: f64::NEG_INFINITY,
            far_when_refused: true,
            background: None,
            rounded: false,
            depth: DepthRule::Range,
            outside: OutsideRule::Clamp,
            depth_no_hit_background: false,
        }
    }

    /// What the program does differently, as the names the diagnosis's judge knows.
    pub(crate) fn truth(&self) -> Vec<String> {
        let mut truth = Vec::new();
        let course = Self::course();
        if self.sample != course.sample {
            truth.push(if self.sample == (0.0, 0.0) {
                "pixel-corners".to_owned()
            } else {
                format!("sample-offset={},{}", self.sample.0, self.sample.1)
            });
        }
        if self.axis_lengths != course.axis_lengths {
            truth.push(format!(
                "zoom={},{}",
                self.axis_lengths.0, self.axis_lengths.1
            ));
        }
        if self.up_along_direction != 0.0 {
            truth.push(format!("t-ramp={}", self.up_along_direction));
        }
        if self.turn_degrees != 0.0 {
            truth.push(format!("axes={}", self.turn_degrees));
        }
        if self.mirrored {
            truth.push("mirrored".to_owned());
        }
        if self.upside_down {
            truth.push("flipped-vertically".to_owned());
        }
        if self.swapped {
            truth.push("swapped-axes".to_owned());
        }
        match self.non_square {
            NonSquare::Centred => {}
            NonSquare::Stretched => truth.push("stretched".to_owned()),
            NonSquare::BottomStrip => truth.push("crop-strip".to_owned()),
            NonSquare::Block => truth.push("square-block".to_owned()),
        }
        if let Some((side, last)) = self.grid {
            truth.push(format!("sample-grid={side},{last}"));
        }
        if let Some((columns, rows)) = self.loops_to {
            truth.push(format!("loops-to={columns},{rows}"));
        }
        match self.keep {
            Keep::Nearest => {}
            Keep::FirstInFile => truth.push("no-depth-test-first".to_owned()),
            Keep::LastInFile => truth.push("no-depth-test-last".to_owned()),
        }
        if self.tmin != course.tmin || self.far_when_refused != course.far_when_refused {
            truth.push(match (self.tmin, self.far_when_refused) {
                (0.0, true) => "tmin-zero".to_owned(),
                (-1.0, false) => "tmin-minus-one".to_owned(),
                (t, true) => format!("tmin={t}"),
                (t, false) => format!("near-root-only={t}"),
            });
        }
        if let Some(b) = self.background {
            truth.push(format!("background={},{},{}", b[0], b[1], b[2]));
        }
        if self.rounded {
            truth.push("rounded".to_owned());
        }
        match self.depth {
            DepthRule::Range => {}
            DepthRule::Reversed => truth.push("depth-reversed".to_owned()),
            DepthRule::PerImage { near, far } => {
                truth.push(format!("depth-per-image={near},{far}"));
            }
            DepthRule::AbsZ => truth.push("depth-quantity=|z|".to_owned()),
            DepthRule::IntegerRange => truth.push("depth-range".to_owned()),
        }
        match self.outside {
            OutsideRule::Clamp => {}
            OutsideRule::Wrap => truth.push("depth-no-clamp".to_owned()),
            OutsideRule::Black => truth.push("depth-outside-black".to_owned()),
            OutsideRule::Colour(c) => {
                truth.push(format!("depth-outside-colour={},{},{}", c[0], c[1], c[2]));
            }
        }
        if self.depth_no_hit_background {
            truth.push("depth-no-hit".to_owned());
        }
        truth
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn normalised(a: [f64; 3]) -> [f64; 3] {
    scale(a, 1.0 / dot(a, a).sqrt())
}

fn byte(value: f64, rounded: bool) -> u8 {
    let v = value * 255.0;
    let v = if rounded { v.round() } else { v.floor() };
    v.clamp(0.0, 255.0) as u8
}

/// The colour and depth images `program` makes of `scene` at `width × height` with `-depth
/// dmin dmax`.
pub(crate) fn render(
    program: &Program,
    scene: &Scene,
    width: u32,
    height: u32,
    dmin: f64,
    dmax: f64,
) -> (RgbImage, RgbImage) {
    let camera = &scene.camera;
    let center = camera.center_world.to_array();
    let direction = normalised(camera.direction_world.to_array());
    let up_given = camera.up_world.to_array();
    // The camera as the program builds it.
    let up_perpendicular = normalised(sub(up_given, scale(direction, dot(up_given, direction))));
    let mut horizontal = normalised(cross(direction, up_perpendicular));
    let (sin, cos) = program.turn_degrees.to_radians().sin_cos();
    let (horizontal_turned, up_perpendicular) = (
        add(scale(horizontal, cos), scale(up_perpendicular, sin)),
        sub(scale(up_perpendicular, cos), scale(horizontal, sin)),
    );
    horizontal = horizontal_turned;
    if program.mirrored {
        horizontal = scale(horizontal, -1.0);
    }
    let horizontal = scale(horizontal, program.axis_lengths.0);
    let up = add(
        scale(up_perpendicular, program.axis_lengths.1),
        scale(direction, program.up_along_direction),
    );
    let size = camera.size_world;
    let (w, h) = (f64::from(width), f64::from(height));
    let longer = w.max(h);
    let background = program.background.unwrap_or_else(|| {
        scene
            .background
            .to_array()
            .map(|c| byte(f64::from(c), program.rounded))
    });
    let colours: Vec<[u8; 3]> = scene
        .spheres
        .iter()
        .map(|s| {
            let c = s
                .material
                .and_then(|m| scene.materials.get(m as usize))
                .map_or([1.0f32; 3], |m| m.diffuse_colour.to_array());
            c.map(|c| byte(f64::from(c), program.rounded))
        })
        .collect();
    let (loop_w, loop_h) = match (program.non_square, program.loops_to) {
        (NonSquare::Block, _) => (width.min(height), width.min(height)),
        (_, Some((columns, rows))) => (columns.min(width), rows.min(height)),
        _ => (width, height),
    };
    let mut t_of = vec![f64::NAN; (width * height) as usize];
    let mut z_of = vec![f64::NAN; (width * height) as usize];
    let mut colour = RgbImage::from_pixel(width, height, Rgb(background));
    // The textbook quadratic with a unit direction: t² + 2bt + c = 0, every sphere in turn.
    let trace = |origin: [f64; 3]| {
        let mut best: Option<(f64, usize)> = None;
        for (index, sphere) in scene.spheres.iter().enumerate() {
            let oc = sub(origin, sphere.center_world.to_array());
            let b = dot(oc, direction);
            let c = dot(oc, oc) - sphere.radius_world * sphere.radius_world;
            let discriminant = b * b - c;
            if discriminant < 0.0 {
                continue;
            }
            let root = discriminant.sqrt();
            let (near, far) = (-b - root, -b + root);
            let t = if near >= program.tmin {
                near
            } else if program.far_when_refused && far >= program.tmin {
                far
            } else {
                continue;
            };
            let take = match (program.keep, best) {
                (_, None) => true,
                (Keep::Nearest, Some((best_t, _))) => t < best_t,
                (Keep::FirstInFile, Some(_)) => false,
                (Keep::LastInFile, Some(_)) => true,
            };
            if take {
                best = Some((t, index));
            }
        }
        best
    };
    let mut written = vec![false; (width * height) as usize];
    let mut put = |i: u32, j: u32, origin: [f64; 3], hit: Option<(f64, usize)>, last: bool| {
        let row = if program.upside_down {
            j
        } else {
            height - 1 - j
        };
        let at = (row * width + i) as usize;
        if let Some((t, index)) = hit
            && (last || !written[at])
        {
            written[at] = true;
            colour.put_pixel(i, row, Rgb(colours[index]));
            let hit = add(origin, scale(direction, t));
            t_of[at] = t;
            z_of[at] = hit[2];
        }
    };
    if let Some((side, last)) = program.grid {
        // Samples on a grid over the whole screen, each written to the pixel it falls in.
        let g = f64::from(side);
        for j in 0..side {
            for i in 0..side {
                let (u, v) = (
                    (f64::from(i) + 0.5) / g - 0.5,
                    (f64::from(j) + 0.5) / g - 0.5,
                );
                let origin = add(
                    center,
                    add(scale(horizontal, u * size), scale(up, v * size)),
                );
                let (x, y) = (
                    (u64::from(i) * u64::from(width) / u64::from(side)) as u32,
                    (u64::from(j) * u64::from(height) / u64::from(side)) as u32,
                );
                put(x, y, origin, trace(origin), last);
            }
        }
    }
    for j in 0..loop_h {
        for i in 0..loop_w {
            if program.grid.is_some() {
                break;
            }
            let (mut x, mut y) = (
                f64::from(i) + program.sample.0,
                f64::from(j) + program.sample.1,
            );
            if program.swapped {
                std::mem::swap(&mut x, &mut y);
            }
            let (u, v) = match program.non_square {
                NonSquare::Centred => ((x - w / 2.0) / longer, (y - h / 2.0) / longer),
                NonSquare::Stretched => (x / w - 0.5, y / h - 0.5),
                NonSquare::BottomStrip => (x / w - 0.5, y / w - 0.5),
                NonSquare::Block => {
                    let side = w.min(h);
                    (x / side - 0.5, y / side - 0.5)
                }
            };
            let origin = add(
                center,
                add(scale(horizontal, u * size), scale(up, v * size)),
            );
            put(i, j, origin, trace(origin), true);
        }
    }
    // The depth image, after the loop (per-image normalisation needs the extremes).
    let finite: Vec<f64> = t_of.iter().copied().filter(|t| t.is_finite()).collect();
    let lowest = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let highest = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let no_hit = if program.depth_no_hit_background {
        background
    } else {
        [0; 3]
    };
    let mut depth = RgbImage::from_pixel(width, height, Rgb(no_hit));
    for (index, &t) in t_of.iter().enumerate() {
        if !t.is_finite() {
            continue;
        }
        let value = match program.depth {
            DepthRule::Range => (dmax - t) / (dmax - dmin),
            DepthRule::Reversed => (t - dmin) / (dmax - dmin),
            DepthRule::PerImage { near, far } => {
                (near + (far - near) * (t - lowest) / (highest - lowest)) / 255.0
            }
            DepthRule::AbsZ => (dmax - z_of[index].abs()) / (dmax - dmin),
            DepthRule::IntegerRange => {
                let (lo, hi) = (dmin.trunc(), dmax.trunc());
                (hi - t) / (hi - lo)
            }
        };
        let grey = match program.outside {
            OutsideRule::Clamp => byte(value, program.rounded),
            OutsideRule::Wrap => {
                let v = value * 255.0;
                let v = if program.rounded {
                    v.round()
                } else {
                    v.floor()
                };
                (v as i64).rem_euclid(256) as u8
            }
            OutsideRule::Black if !(0.0..=1.0).contains(&value) => 0,
            OutsideRule::Black => byte(value, program.rounded),
            OutsideRule::Colour(c) if !(0.0..=1.0).contains(&value) => {
                let (x, y) = (index as u32 % width, index as u32 / width);
                depth.put_pixel(x, y, Rgb(c));
                continue;
            }
            OutsideRule::Colour(_) => byte(value, program.rounded),
        };
        let (x, y) = (index as u32 % width, index as u32 / width);
        depth.put_pixel(x, y, Rgb([grey; 3]));
    }
    (colour, depth)
}
