//! The pixel trace, the course's way of debugging a ray caster: the exact computation behind one
//! pixel in the course's terms, as plain text a student can set beside their own program's
//! printout — the pixel's sample point on the screen, the ray's origin and direction, each sphere
//! in file order with its discriminant and roots, accepted or refused (tmin), the hit chosen, its
//! colour, and the depth grey with its arithmetic.
//!
//! The numbers are the course's model evaluated in f64: `d = normalize(direction)`,
//! `horizontal = normalize(d × up)`, `screen_up = horizontal × d`, one pixel `size / max(W, H)`
//! wide, pixel (x, y) (y = 0 the bottom row) sampled at its centre, the ray `o + t·d` from the
//! screen plane, tmin = −∞ (an orthographic camera sees a sphere's near root wherever its disc
//! covers the pixel), the nearest hit kept and, on a tie, the first sphere in the file. The
//! discriminant is computed as `r² − |f − (f·d)d|²` with `f = o − c` (no cancellation), and
//! printed with the textbook's `b² − 4ac` (a = 1, b = 2 f·d), which is four times it.

use std::fmt::Write as _;

use glam::DVec3;

use crate::geometry::camera::{CameraBasis, PixelGrid};
use crate::render::View;
use crate::render::depth_map::{DepthRange, quantize_f32, quantize_f64};
use crate::scene::Scene;

/// One sphere as the ray meets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphereTrace {
    /// The sphere's place in the file (0-based).
    pub index: usize,
    /// Its centre, world.
    pub center_world: DVec3,
    /// Its radius, world.
    pub radius_world: f64,
    /// `f·d` with `f = o − c`: half the textbook's b.
    pub half_b: f64,
    /// `r² − |f − (f·d)d|²`: a quarter of the textbook's `b² − 4ac`; negative: a miss.
    pub quarter_discriminant: f64,
    /// The roots `−f·d ∓ √Δ` (near, far), where it is hit.
    pub roots: Option<(f64, f64)>,
}

/// The trace of one pixel.
#[derive(Debug, Clone, PartialEq)]
pub struct PixelTrace {
    /// Image size, pixels.
    pub size_px: (u32, u32),
    /// Pixel column, 0 at the left.
    pub x_px: u32,
    /// Pixel row, 0 at the bottom (the course's convention).
    pub y_up_px: u32,
    /// One pixel's side, world: `size / max(W, H)`.
    pub pixel_size_world: f64,
    /// The sample point on the screen, (u, v) from the camera centre, world.
    pub screen_uv: (f64, f64),
    /// The camera's basis.
    pub basis: CameraBasis,
    /// The ray's origin, world: `centre + u·horizontal + v·screen_up`.
    pub origin_world: DVec3,
    /// Every sphere in file order.
    pub spheres: Vec<SphereTrace>,
    /// The sphere seen (its index in the file) and t, if any.
    pub hit: Option<(usize, f64)>,
    /// The colour seen (the sphere's diffuse colour, or the background).
    pub colour: [f32; 3],
    /// Its bytes, `floor(255·colour)` per channel.
    pub colour_bytes: [u8; 3],
    /// The depth range of the depth image, if known.
    pub depth_range: Option<DepthRange>,
}

/// Why a pixel cannot be traced.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TraceError {
    /// The pixel is not in the image.
    #[error("pixel ({x}, {y}) is outside the {width}×{height} image (x 0 … {}, y 0 … {})", width.saturating_sub(1), height.saturating_sub(1))]
    OutsideImage {
        /// The column asked for.
        x: u32,
        /// The row asked for.
        y: u32,
        /// The image's width.
        width: u32,
        /// The image's height.
        height: u32,
    },
    /// The camera has no basis (a zero direction, or up along it).
    #[error("the camera cannot be used: {0}")]
    Camera(String),
}

/// Traces pixel (`x_px`, `y_up_px`) (row 0 at the bottom) of `scene` through `view`; the depth
/// grey over `depth_range` when one is known.
pub fn trace_pixel(
    scene: &Scene,
    view: &View,
    x_px: u32,
    y_up_px: u32,
    depth_range: Option<DepthRange>,
) -> Result<PixelTrace, TraceError> {
    let (width, height) = (view.width_px, view.height_px);
    if x_px >= width || y_up_px >= height {
        return Err(TraceError::OutsideImage {
            x: x_px,
            y: y_up_px,
            width,
            height,
        });
    }
    let basis = CameraBasis::new(view.direction_world, view.up_world)
        .map_err(|error| TraceError::Camera(error.to_string()))?;
    let grid = PixelGrid::new(width, height, view.size_world);
    let (u, v) = (
        grid.u_of_column(f64::from(x_px)),
        grid.v_of_row(f64::from(y_up_px)),
    );
    let origin = view.center_world + u * basis.horizontal + v * basis.screen_up;
    let d = basis.direction;
    let mut spheres = Vec::with_capacity(scene.spheres.len());
    let mut hit: Option<(usize, f64)> = None;
    for (index, sphere) in scene.spheres.iter().enumerate() {
        let f = origin - sphere.center_world;
        let half_b = f.dot(d);
        let radius = sphere.radius_world;
        let quarter_discriminant = radius * radius - (f - half_b * d).length_squared();
        let roots = (quarter_discriminant >= 0.0).then(|| {
            let root = quarter_discriminant.sqrt();
            (-half_b - root, -half_b + root)
        });
        if let Some((near, _)) = roots
            && hit.is_none_or(|(_, t)| near < t)
        {
            hit = Some((index, near));
        }
        spheres.push(SphereTrace {
            index,
            center_world: sphere.center_world,
            radius_world: radius,
            half_b,
            quarter_discriminant,
            roots,
        });
    }
    let colour = match hit {
        Some((index, _)) => scene.sphere_colour(&scene.spheres[index]),
        None => scene.background,
    }
    .to_array();
    Ok(PixelTrace {
        size_px: (width, height),
        x_px,
        y_up_px,
        pixel_size_world: grid.pixel_size_world,
        screen_uv: (u, v),
        basis,
        origin_world: origin,
        spheres,
        hit,
        colour,
        colour_bytes: colour.map(quantize_f32),
        depth_range,
    })
}

/// `v` as `(x, y, z)`, each with up to 17 significant digits.
fn vector(v: DVec3) -> String {
    // (+ 0.0 writes a negative zero as 0.)
    format!("({}, {}, {})", v.x + 0.0, v.y + 0.0, v.z + 0.0)
}

impl PixelTrace {
    /// The depth image's grey at this pixel, in [0, 1] (0: no hit), where the range is known.
    pub fn grey(&self) -> Option<f64> {
        let range = self.depth_range?;
        Some(self.hit.map_or(0.0, |(_, t)| range.grey(t)))
    }

    /// The depth image's byte at this pixel, where the range is known.
    pub fn grey_byte(&self) -> Option<u8> {
        self.grey().map(quantize_f64)
    }

    /// The trace as plain text, one step a line.
    pub fn text(&self) -> String {
        self.text_sized(self.text_bytes())
    }

    /// [`Self::text`], made in a string of `bytes` (what [`Self::text_bytes`] counted).
    pub fn text_sized(&self, bytes: u64) -> String {
        let mut out = String::with_capacity(usize::try_from(bytes).unwrap_or(0));
        let (width, height) = self.size_px;
        let (u, v) = self.screen_uv;
        let _ = writeln!(
            out,
            "pixel: x {} y {} of W×H = {width}×{height} (y from the bottom; row {} from the top)",
            self.x_px,
            self.y_up_px,
            height - 1 - self.y_up_px
        );
        let _ = writeln!(
            out,
            "pixel size: pixel = size / max(W, H) = {} (size: the camera's)",
            self.pixel_size_world
        );
        let _ = writeln!(
            out,
            "sample point: u = (x + 0.5 − W/2)·pixel = {u}, v = (y + 0.5 − H/2)·pixel = {v}"
        );
        let _ = writeln!(
            out,
            "basis: d = normalize(direction) = {}, horizontal = normalize(d × up) = {}, \
             screen_up = horizontal × d = {}",
            vector(self.basis.direction),
            vector(self.basis.horizontal),
            vector(self.basis.screen_up)
        );
        let _ = writeln!(
            out,
            "ray: origin = camera centre + u·horizontal + v·screen_up = {}, direction = d",
            vector(self.origin_world)
        );
        let _ = writeln!(
            out,
            "tmin: −∞ (orthographic: the near root counts wherever the disc covers the pixel)"
        );
        let _ = writeln!(
            out,
            "each sphere (centre C, radius r): f = origin − C; the textbook's a·t² + b·t + c = 0 has \
             a = d·d = 1, b = 2 f·d and c = f·f − r², so Δ/4 = (f·d)² − c = r² − |f − (f·d)d|² and the roots \
             are t0, t1 = −f·d ∓ √(Δ/4)"
        );
        // One line per sphere: a million spheres make some 150 MB of text, so it is measured
        // first and made in a string of its size, with room for the lines after it and what the
        // command adds (grown by doubling, the old and the new buffer were both held: up to
        // three times the text, and a peak that varied from run to run).
        self.write_sphere_lines(&mut out);
        let [r, g, b] = self.colour;
        let [rb, gb, bb] = self.colour_bytes;
        if let Some((index, t)) = self.hit {
            let _ = writeln!(
                out,
                "hit: sphere {index} at t = {t} (point {})",
                vector(self.origin_world + t * self.basis.direction)
            );
            let _ = writeln!(
                out,
                "colour: its diffuse colour ({r}, {g}, {b}) → floor(255·colour) = {rb} {gb} {bb}"
            );
            match (self.depth_range, self.grey(), self.grey_byte()) {
                (Some(range), Some(grey), Some(byte)) => {
                    let _ = writeln!(
                        out,
                        "depth: over -depth DMIN DMAX = {} {}, grey = clamp((DMAX − t)/(DMAX − DMIN), 0, \
                         1) = ({} − {t})/({} − {}) → {grey} → floor(255·grey) = {byte}",
                        range.min_t, range.max_t, range.max_t, range.max_t, range.min_t,
                    );
                }
                _ => {
                    let _ = writeln!(
                        out,
                        "depth: no depth range (give -depth DMIN DMAX FILE for the grey)"
                    );
                }
            }
        } else {
            let _ = writeln!(out, "hit: none");
            let _ = writeln!(
                out,
                "colour: the background colour ({r}, {g}, {b}) → floor(255·colour) = {rb} {gb} {bb}"
            );
            let _ = writeln!(out, "depth: no hit → grey 0");
        }
        out
    }

    /// The bytes its records hold.
    pub fn records_bytes(&self) -> u64 {
        (self.spheres.capacity() * std::mem::size_of::<SphereTrace>()) as u64
    }

    /// The bytes of its text at most, counted without making it (a number prints in full, so a
    /// line is 200 bytes or a few thousand): the sphere lines and the room kept after them.
    pub fn text_bytes(&self) -> u64 {
        (self.sphere_lines_bytes() + TEXT_ROOM_BYTES) as u64
    }

    /// The length of the sphere lines, counted without making them.
    fn sphere_lines_bytes(&self) -> usize {
        let mut measure = CountBytes::default();
        self.write_sphere_lines(&mut measure);
        measure.0
    }

    /// Writes one line per sphere, in file order, to `out`.
    fn write_sphere_lines(&self, out: &mut impl std::fmt::Write) {
        for sphere in &self.spheres {
            let _ = write!(
                out,
                "sphere {}: centre {} radius {}: f·d = {}, Δ/4 = r² − |f − (f·d)d|² = {} \
                 (b² − 4ac = {})",
                sphere.index,
                vector(sphere.center_world),
                sphere.radius_world,
                sphere.half_b,
                sphere.quarter_discriminant,
                4.0 * sphere.quarter_discriminant
            );
            match sphere.roots {
                None => {
                    let _ = writeln!(out, ": missed (Δ < 0)");
                }
                Some((near, far)) => {
                    let seen = match self.hit {
                        Some((index, _)) if index == sphere.index => "the nearest: seen",
                        _ => "accepted, not the nearest",
                    };
                    let _ = writeln!(
                        out,
                        ": roots t0 = −f·d − √(Δ/4) = {near}, t1 = {far}; t0 {seen}"
                    );
                }
            }
        }
    }
}

/// Room a trace's text keeps beyond its sphere lines: its last lines, and the comparison's
/// lines and statistics the command prints after it.
const TEXT_ROOM_BYTES: usize = 64 << 10;

/// Counts the bytes written to it.
#[derive(Default)]
struct CountBytes(usize);

impl std::fmt::Write for CountBytes {
    fn write_str(&mut self, text: &str) -> std::fmt::Result {
        self.0 += text.len();
        Ok(())
    }
}

/// The t a depth byte `grey` of an image over `range` stands for: the interval of t that
/// `floor(255·(DMAX − t)/(DMAX − DMIN))` maps to it (`None` for 0 and 255, which also take
/// everything beyond the range).
pub fn t_of_grey(range: DepthRange, grey: u8) -> Option<(f64, f64)> {
    if grey == 0 || grey == 255 {
        return None;
    }
    let width = range.max_t - range.min_t;
    let t_at = |level: f64| range.max_t - level / 255.0 * width;
    let (a, b) = (t_at(f64::from(grey) + 1.0), t_at(f64::from(grey)));
    Some((a.min(b), a.max(b)))
}

impl PixelTrace {
    /// Their colour pixel `rgb` beside the exact bytes, as a line.
    pub fn their_colour_line(&self, [r, g, b]: [u8; 3]) -> String {
        let [er, eg, eb] = self.colour_bytes;
        format!("theirs, colour: {r} {g} {b} (exact {er} {eg} {eb})\n")
    }

    /// Their depth grey beside the exact one, and what it stands for: with `drew` (what the
    /// fitted model of their program draws at this pixel), their no-hit grey, a hit outside
    /// their range, or the t their grey stands for over their own range; without, the t it stands
    /// for over the trace's range, as a line.
    pub fn their_depth_line(&self, grey: u8, drew: Option<TheirDepth>) -> String {
        let exact = self
            .grey_byte()
            .map_or_else(|| "unknown".to_owned(), |byte| byte.to_string());
        let head = format!("theirs, depth: grey {grey} (exact {exact})");
        match drew {
            Some(TheirDepth::NoHit) => {
                return format!(
                    "{head}: {grey} is your program's no-hit grey: your program hit nothing here\n"
                );
            }
            Some(TheirDepth::Outside { white_t, black_t }) => {
                return format!(
                    "{head}: your program's hit here lies outside your range (white at t = \
                     {white_t}, black at t = {black_t}), drawn {grey}\n"
                );
            }
            Some(TheirDepth::Hit { white_t, black_t }) if grey != 0 && grey != 255 => {
                // Their grey is floor(255·(black − t)/(black − white)).
                let t_at = |level: f64| black_t - level / 255.0 * (black_t - white_t);
                let (a, b) = (t_at(f64::from(grey)), t_at(f64::from(grey) + 1.0));
                return format!(
                    "{head}: over your range (white at t = {white_t}, black at t = {black_t}) \
                     your grey stands for t in [{}, {})\n",
                    a.min(b),
                    a.max(b)
                );
            }
            Some(TheirDepth::Hit { white_t, black_t }) => {
                return format!(
                    "{head}: grey {grey} is an end of your range (white at t = {white_t}, black \
                     at t = {black_t}), or beyond it\n"
                );
            }
            Some(TheirDepth::Unexplained) | None => {}
        }
        let unexplained = if drew == Some(TheirDepth::Unexplained) {
            " (a pixel the answer does not explain)"
        } else {
            ""
        };
        match self
            .depth_range
            .map(|range| (range, t_of_grey(range, grey)))
        {
            Some((range, Some((low, high)))) => format!(
                "{head}: over {} … {} their grey stands for t in [{low}, {high}){unexplained}\n",
                range.min_t, range.max_t
            ),
            Some((_, None)) => format!(
                "{head}: grey {grey} is the range's end, or beyond it (or no hit, for \
                 0){unexplained}\n"
            ),
            None => format!("{head}{unexplained}\n"),
        }
    }
}

/// What their program drew at a traced pixel's depth, as the fitted model of it says: what the
/// trace says their grey stands for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TheirDepth {
    /// Their program's ray hits nothing here: their grey is its no-hit grey.
    NoHit,
    /// Their program's hit lies outside its own range (white at `white_t`, black at `black_t`).
    Outside {
        /// The t their program draws white.
        white_t: f64,
        /// The t their program draws black.
        black_t: f64,
    },
    /// Their program drew a hit's t over its own range.
    Hit {
        /// The t their program draws white.
        white_t: f64,
        /// The t their program draws black.
        black_t: f64,
    },
    /// The fitted model draws this pixel otherwise than their image: nothing is known of it.
    Unexplained,
}
