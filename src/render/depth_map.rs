//! The depth mapping (t → grey) and 8-bit quantisation, in one place.
//!
//! docs/spec.md: `grey = clamp((depth_max − t) / (depth_max − depth_min), 0, 1)`; near is white, far is
//! black, pixels with no hit are black. Decisions where docs/spec.md is silent:
//! * `depth_min > depth_max` is allowed and gives the **reversed ramp** the formula gives (near
//!   black, far white) — a way to look at a scene from behind; no-hit pixels stay black.
//! * `depth_min == depth_max` is a **step**: t ≤ depth_min is white, t > depth_min black (the limit
//!   of the ramp as the range shrinks to zero width); no division by zero.
//!
//! The mapping is computed in f64 from an f64 t, so narrow ranges far away stay exact.
//!
//! Besides grey, the depth image can go through a perceptual colour map ([`DepthColourMap`]:
//! turbo, viridis) applied to the same grey value (near = the map's bright/warm end). In colour
//! maps, pixels with no hit are black, which neither map contains, so "nothing there" never looks
//! like "far away". The course's grey image keeps no-hit black (docs/spec.md); the viewer can mark no-hit
//! pixels on screen in a colour far from the map's (the viewer's settings, `src/app/settings.rs`).

/// The range of t mapped onto the grey ramp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DepthRange {
    /// t shown white.
    pub min_t: f64,
    /// t shown black.
    pub max_t: f64,
}

impl DepthRange {
    /// The range a render takes when no depth image is asked for: only the colour image is
    /// written, and it does not depend on the range.
    pub const UNUSED: Self = Self {
        min_t: 0.0,
        max_t: 1.0,
    };

    /// The range `[min_t, max_t]`.
    pub fn new(min_t: f64, max_t: f64) -> Self {
        Self { min_t, max_t }
    }

    /// Grey level in [0, 1] of a hit at `t` (`t = +∞` means no hit: black).
    pub fn grey(&self, t: f64) -> f64 {
        if t == f64::INFINITY || t.is_nan() {
            return 0.0;
        }
        let width = self.max_t - self.min_t;
        if width == 0.0 {
            return if t <= self.min_t { 1.0 } else { 0.0 };
        }
        ((self.max_t - t) / width).clamp(0.0, 1.0)
    }

    /// 8-bit grey of a hit at `t`.
    pub fn grey_u8(&self, t: f64) -> u8 {
        quantize_f64(self.grey(t))
    }
}

/// How t values become the depth image's colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "gui", derive(serde::Serialize, serde::Deserialize))]
pub enum DepthColourMap {
    /// The course's grey ramp: near white, far black, no hit black.
    #[default]
    Grey,
    /// Google's turbo rainbow: near dark red, far dark blue; no hit black.
    Turbo,
    /// Matplotlib's viridis: near yellow, far dark purple; no hit black.
    Viridis,
}

impl DepthColourMap {
    /// Every map, in the order menus list them.
    pub(crate) const ALL: [Self; 3] = [Self::Grey, Self::Turbo, Self::Viridis];

    /// The name used on the command line (`-depth_colormap`) and in menus.
    pub fn name(self) -> &'static str {
        match self {
            Self::Grey => "grey",
            Self::Turbo => "turbo",
            Self::Viridis => "viridis",
        }
    }

    /// Every map's name, as a sentence lists them ("grey, turbo or viridis"): the usage text
    /// and the error for a name that is none of them take it from [`Self::ALL`].
    pub fn names_listed() -> String {
        let names: Vec<&str> = Self::ALL.iter().map(|map| map.name()).collect();
        match names.split_last() {
            Some((last, [])) => (*last).to_owned(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => String::new(),
        }
    }

    /// The map a name stands for (as [`Self::name`] spells it; `gray` is accepted too).
    pub(crate) fn from_name(name: &str) -> Option<Self> {
        match name {
            "grey" | "gray" => Some(Self::Grey),
            "turbo" => Some(Self::Turbo),
            "viridis" => Some(Self::Viridis),
            _ => None,
        }
    }

    /// The 8-bit colour of a grey value `grey` in [0, 1] (1 = near). Grey quantises by
    /// truncation exactly as [`DepthRange::grey_u8`] does, so the grey map is the course's image.
    pub(crate) fn rgb_of_grey(self, grey: f64) -> [u8; 3] {
        // Turbo's darkest tenth is nearly black, which would read as "no hit": the far end
        // starts at its blue instead.
        let (gradient, far_end) = match self {
            Self::Grey => return [quantize_f64(grey); 3],
            Self::Turbo => (colorous::TURBO, TURBO_FAR_END),
            Self::Viridis => (colorous::VIRIDIS, 0.0),
        };
        let grey = if grey.is_nan() {
            0.0
        } else {
            grey.clamp(0.0, 1.0)
        };
        let colour = gradient.eval_continuous(far_end + (1.0 - far_end) * grey);
        [colour.r, colour.g, colour.b]
    }

    /// The colour of a pixel whose nearest hit is at `t` (`+∞`: no hit) over `range`.
    /// No-hit pixels are `no_hit` (use [`Self::file_no_hit`] for files).
    pub(crate) fn rgb(self, range: &DepthRange, t: f64, no_hit: [u8; 3]) -> [u8; 3] {
        if t == f64::INFINITY || t.is_nan() {
            no_hit
        } else {
            self.rgb_of_grey(range.grey(t))
        }
    }

    /// What a no-hit pixel looks like in a written file, whatever the map: black (the course's
    /// choice for grey; in the colour maps black is no value of the map).
    pub(crate) const FILE_NO_HIT: [u8; 3] = [0, 0, 0];
}

impl std::fmt::Display for DepthColourMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// How the t of a frame's pixels become their 8-bit depth colours: a range, a colour map and the
/// colour of no-hit pixels. The one place where t becomes a depth colour, for whole frames and
/// strips of them alike.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DepthPainter {
    range: DepthRange,
    map: DepthColourMap,
    no_hit: [u8; 3],
    /// For the grey map over a range of finite, non-zero width: its far end and width, mapped
    /// without branches ([`grey_level`]).
    grey_ramp: Option<(f64, f64)>,
}

/// Pixels mapped per parallel task.
const PIXELS_PER_TASK: usize = 16_384;

impl DepthPainter {
    /// Maps t over `range` through `map`; no-hit pixels get `no_hit`.
    pub(crate) fn new(range: DepthRange, map: DepthColourMap, no_hit: [u8; 3]) -> Self {
        let width = range.max_t - range.min_t;
        let plain_grey = map == DepthColourMap::Grey
            && width.is_finite()
            && width != 0.0
            && range.max_t.is_finite();
        Self {
            range,
            map,
            no_hit,
            grey_ramp: plain_grey.then_some((range.max_t, width)),
        }
    }

    /// The colour of a pixel whose nearest hit is at `t` (`+∞`: no hit). On the grey ramp
    /// without branches on t; which mapping applies is the same for every pixel, so that branch
    /// is always predicted.
    #[inline]
    pub(crate) fn colour_of(&self, t: f64) -> [u8; 3] {
        match self.grey_ramp {
            Some((max_t, width)) => {
                grey_level(t, max_t, width).map_or(self.no_hit, |grey| [grey; 3])
            }
            None => self.map.rgb(&self.range, t, self.no_hit),
        }
    }

    /// The pixels of `t` (storage order), each made from its colour by `pixel` (the viewer
    /// makes texture pixels), in parallel.
    pub(crate) fn pixels<P: Send>(&self, t: &[f64], pixel: impl Fn([u8; 3]) -> P + Sync) -> Vec<P> {
        use rayon::prelude::*;
        t.par_iter()
            .with_min_len(PIXELS_PER_TASK)
            .map(|&t| pixel(self.colour_of(t)))
            .collect()
    }

    /// The colours of the pixels of `t` into `rgb` (as long), on this thread.
    pub(crate) fn paint(&self, t: &[f64], rgb: &mut [[u8; 3]]) {
        for (rgb, &t) in rgb.iter_mut().zip(t) {
            *rgb = self.colour_of(t);
        }
    }
}

/// The 8-bit grey ([`DepthRange::grey_u8`]) of a hit at `t` over a range ending at `max_t`,
/// `width` wide (finite, not zero); `None` for no hit. Without branches on t (which pixels
/// hit, and where they fall on the ramp, is unpredictable in a dense frame): the same
/// correctly rounded operations as the general mapping, so the same greys.
#[inline]
fn grey_level(t: f64, max_t: f64, width: f64) -> Option<u8> {
    // clamp((max − t) / width, 0, 1) (no NaN: t is finite or −∞ where it counts), truncated to
    // 0..=255.
    let level = ((max_t - t) / width).clamp(0.0, 1.0) * 255.0;
    (t < f64::INFINITY).then_some(level as u8)
}

/// Where on colorous's turbo gradient the far end of the depth range lies.
const TURBO_FAR_END: f64 = 0.1;

/// 16-bit quantisation by truncation, `clamp(floor(c·65535), 0, 65535)`, for 16-bit depth PNGs.
/// NaN maps to 0.
pub(crate) fn quantize_u16(c: f64) -> u16 {
    // Truncation is floor for the values kept (≥ 0), without a library call per pixel.
    let scaled = c * 65535.0;
    if scaled >= 65535.0 {
        u16::MAX
    } else if scaled >= 0.0 {
        scaled as u16
    } else {
        0
    }
}

/// 8-bit quantisation by truncation, `clamp(floor(c·255), 0, 255)`, for colour channels (f32, as the
/// course computed them). NaN maps to 0.
pub(crate) fn quantize_f32(c: f32) -> u8 {
    // Truncation is floor for the values kept (≥ 0), without a library call per pixel.
    let scaled = c * 255.0;
    if scaled >= 255.0 {
        255
    } else if scaled >= 0.0 {
        scaled as u8
    } else {
        0
    }
}

/// 8-bit quantisation by truncation of an f64 value in [0, 1]. NaN maps to 0.
pub(crate) fn quantize_f64(c: f64) -> u8 {
    // Truncation is floor for the values kept (≥ 0), without a library call per pixel.
    let scaled = c * 255.0;
    if scaled >= 255.0 {
        255
    } else if scaled >= 0.0 {
        scaled as u8
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_is_white_far_is_black_and_outside_is_clamped() {
        let range = DepthRange::new(9.0, 10.0);
        assert_eq!(range.grey(9.0), 1.0);
        assert_eq!(range.grey(10.0), 0.0);
        assert_eq!(range.grey(9.5), 0.5);
        assert_eq!(range.grey(-100.0), 1.0);
        assert_eq!(range.grey(100.0), 0.0);
        assert_eq!(range.grey_u8(9.5), 127);
        assert_eq!(range.grey_u8(9.0), 255);
    }

    #[test]
    fn no_hit_is_black() {
        assert_eq!(DepthRange::new(9.0, 10.0).grey_u8(f64::INFINITY), 0);
        assert_eq!(DepthRange::new(10.0, 9.0).grey_u8(f64::INFINITY), 0);
        assert_eq!(DepthRange::new(5.0, 5.0).grey_u8(f64::INFINITY), 0);
    }

    #[test]
    fn reversed_range_gives_a_reversed_ramp() {
        let range = DepthRange::new(10.0, 9.0);
        assert_eq!(range.grey(9.0), 0.0);
        assert_eq!(range.grey(10.0), 1.0);
        assert_eq!(range.grey(9.25), 0.25);
    }

    #[test]
    fn empty_range_is_a_step() {
        let range = DepthRange::new(5.0, 5.0);
        assert_eq!(range.grey(4.0), 1.0);
        assert_eq!(range.grey(5.0), 1.0);
        assert_eq!(range.grey(5.000001), 0.0);
    }

    #[test]
    fn narrow_range_far_away_keeps_its_grey_levels() {
        let range = DepthRange::new(99_999.996, 100_000.001_5);
        // Midpoint of the range is mid-grey; f32 could not even represent these t apart.
        let mid = 0.5 * (99_999.996 + 100_000.001_5);
        assert_eq!(range.grey_u8(mid), 127);
        assert_eq!(range.grey_u8(99_999.996), 255);
        assert_eq!(range.grey_u8(100_000.001_5), 0);
    }

    #[test]
    fn colour_maps_keep_grey_exact_and_no_hit_apart() {
        let range = DepthRange::new(9.0, 10.0);
        for t in [8.0, 9.0, 9.3, 9.999, 10.0, 11.0] {
            assert_eq!(
                DepthColourMap::Grey.rgb(&range, t, [0; 3]),
                [range.grey_u8(t); 3]
            );
        }
        for map in [DepthColourMap::Turbo, DepthColourMap::Viridis] {
            let near = map.rgb(&range, 9.0, [0; 3]);
            let far = map.rgb(&range, 10.0, [0; 3]);
            assert_ne!(near, far, "{map}");
            // No value of the map is black: no hit stays distinguishable from far.
            for step in 0..=1000 {
                assert_ne!(
                    map.rgb_of_grey(f64::from(step) / 1000.0),
                    [0, 0, 0],
                    "{map}"
                );
            }
            assert_eq!(
                map.rgb(&range, f64::INFINITY, DepthColourMap::FILE_NO_HIT),
                [0, 0, 0]
            );
            assert_eq!(map.rgb_of_grey(f64::NAN), map.rgb_of_grey(0.0));
        }
        // Turbo's far end is blue, its near end red; viridis's near end is yellow.
        let [r, _, b] = DepthColourMap::Turbo.rgb_of_grey(0.0);
        assert!(b > r);
        let [r, g, b] = DepthColourMap::Viridis.rgb_of_grey(1.0);
        assert!(r > 200 && g > 200 && b < 100);
        for map in DepthColourMap::ALL {
            assert_eq!(DepthColourMap::from_name(map.name()), Some(map));
        }
        assert_eq!(DepthColourMap::from_name("jet"), None);
    }

    #[test]
    fn grey_levels_are_the_greys_of_the_general_mapping() {
        // t all over the range and beyond it, on the edges of grey levels (t at min + k·width/255),
        // infinite and NaN; ramps of either direction, narrow and far away.
        let mut rng = crate::render::rng::SplitMix64::new(12);
        let ranges = [
            DepthRange::new(9.0, 10.0),
            DepthRange::new(10.0, 9.0),
            DepthRange::new(-3.0, 250.0),
            DepthRange::new(1e7, 1e7 + 1e-3),
        ];
        for range in ranges {
            let width = range.max_t - range.min_t;
            let mut t: Vec<f64> = (0..20_000)
                .map(|_| range.min_t + width * rng.uniform(-0.2, 1.2))
                .collect();
            t.extend((0..=255).map(|k| range.min_t + width * f64::from(k) / 255.0));
            t.extend([
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NAN,
                range.min_t,
                range.max_t,
            ]);
            for &t in &t {
                let wanted = (t != f64::INFINITY && !t.is_nan()).then(|| range.grey_u8(t));
                assert_eq!(
                    grey_level(t, range.max_t, width),
                    wanted,
                    "t {t} over {range:?}"
                );
            }
        }
    }

    #[test]
    fn painting_and_collecting_give_every_map_its_colours() {
        // Past one parallel task, over the grey ramp, a step, a reversed range and colour maps.
        let mut rng = crate::render::rng::SplitMix64::new(3);
        let t: Vec<f64> = (0..40_000)
            .map(|i| match i % 97 {
                0 => f64::INFINITY,
                1 => f64::NAN,
                _ => rng.uniform(8.0, 11.0),
            })
            .collect();
        // And every grey level's edge of the first range.
        let t: Vec<f64> = t
            .into_iter()
            .chain((0..=255).map(|k| 9.0 + f64::from(k) / 255.0))
            .collect();
        for (range, map, no_hit) in [
            (DepthRange::new(9.0, 10.0), DepthColourMap::Grey, [0; 3]),
            (
                DepthRange::new(10.0, 9.0),
                DepthColourMap::Grey,
                [24, 36, 96],
            ),
            (DepthRange::new(9.5, 9.5), DepthColourMap::Grey, [0; 3]),
            (DepthRange::new(9.0, 10.0), DepthColourMap::Turbo, [0; 3]),
            (
                DepthRange::new(9.0, 10.0),
                DepthColourMap::Viridis,
                [24, 36, 96],
            ),
        ] {
            let painter = DepthPainter::new(range, map, no_hit);
            let wanted: Vec<[u8; 3]> = t.iter().map(|&t| map.rgb(&range, t, no_hit)).collect();
            assert_eq!(painter.pixels(&t, |rgb| rgb), wanted, "{map} {range:?}");
            let mut painted = vec![[7u8; 3]; t.len()];
            painter.paint(&t, &mut painted);
            assert_eq!(painted, wanted, "{map} {range:?}");
        }
    }

    #[test]
    fn sixteen_bit_quantisation_truncates_and_clamps() {
        assert_eq!(quantize_u16(1.0), 65535);
        assert_eq!(quantize_u16(0.5), 32767);
        assert_eq!(quantize_u16(-1.0), 0);
        assert_eq!(quantize_u16(f64::NAN), 0);
        assert_eq!(quantize_u16(2.0), 65535);
    }

    #[test]
    fn quantisation_truncates_and_clamps() {
        assert_eq!(quantize_f32(0.1), 25);
        assert_eq!(quantize_f32(1.0), 255);
        assert_eq!(quantize_f32(1.5), 255);
        assert_eq!(quantize_f32(-0.2), 0);
        assert_eq!(quantize_f32(f32::NAN), 0);
        assert_eq!(quantize_f64(0.999), 254);
    }
}
