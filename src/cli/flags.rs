//! The flag table: every flag's spelling, the values that follow it and its help line, in one
//! place. Parsing ([`super::RawArgs::parse`]), the usage text ([`usage`]) and writing a request
//! back to arguments ([`super::RenderRequest::to_arguments`]) all read it, so renaming a flag is
//! a one-line change here; the rest of the program names flags by [`Flag`].

use crate::output::{ImageFormat, RawDepthFormat};
use crate::render::depth_map::DepthColourMap;
use std::fmt::{self, Write as _};
use std::path::Path;

/// The word that starts the grading command (`raytracer grade …`).
pub const GRADE_WORD: &str = "grade";

/// The grading command's synopsis, for the usage text and its errors.
pub const GRADE_SYNOPSIS: &str = "grade ASSIGNMENT SUBMISSIONS -o REPORT [--memory MB]";

/// What `raytracer -version` prints (and the viewer's help overlay shows): the version and the
/// commit the program was built from (`+changes` where tracked files differed from it; build.rs).
pub const VERSION_LINE: &str = concat!(
    "raytracer ",
    env!("CARGO_PKG_VERSION"),
    " (commit ",
    env!("RAYTRACER_COMMIT"),
    ")"
);

/// A command-line flag.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Flag {
    /// The scene file.
    Input,
    /// Image size.
    Size,
    /// Colour image.
    Output,
    /// 8-bit depth image.
    Depth,
    /// Colour map of the depth image.
    DepthColourMap,
    /// 16-bit depth PNG.
    Depth16,
    /// Lossless depth (PFM, EXR).
    DepthRaw,
    /// Uniform supersampling.
    UniformSamples,
    /// Jittered supersampling.
    JitteredSamples,
    /// Random supersampling.
    RandomSamples,
    /// Box reconstruction filter.
    BoxFilter,
    /// Tent reconstruction filter.
    TentFilter,
    /// Gaussian reconstruction filter.
    GaussianFilter,
    /// A colour image to compare with the exact one.
    CompareOutput,
    /// A depth image to compare with the exact one.
    CompareDepth,
    /// The difference picture of a comparison.
    Diff,
    /// How the comparison's answer is printed: lines or JSON.
    CompareFormat,
    /// Timings and counts after rendering.
    Stats,
    /// The computation behind one pixel, printed.
    Trace,
    /// The usage text.
    Help,
    /// The version and the commit built from.
    Version,
}

/// One row of the table.
pub(crate) struct FlagSpec {
    pub(crate) flag: Flag,
    /// The spelling on the command line.
    pub(crate) name: &'static str,
    /// Other spellings accepted (never written).
    pub(crate) aliases: &'static [&'static str],
    /// Names of the values that follow the flag, as the usage text shows them.
    pub(crate) values: &'static [&'static str],
    /// What the flag does, for the usage text.
    pub(crate) help: &'static str,
}

/// The flags that name a file the request writes, in the order the outputs are listed, written
/// back and checked ([`super::Outputs::each`]).
pub(crate) const OUTPUT_FLAGS: [Flag; 4] =
    [Flag::Output, Flag::Depth, Flag::Depth16, Flag::DepthRaw];

/// Whether `flag` can write (or, for the comparison's flags, read) a file named `path`: its
/// extension names a format the flag takes.
pub(crate) fn format_known(flag: Flag, path: &Path) -> bool {
    match flag {
        Flag::DepthRaw => RawDepthFormat::from_path(path).is_some(),
        Flag::Depth16 => matches!(ImageFormat::from_path(path), Ok(ImageFormat::Png)),
        _ => ImageFormat::from_path(path).is_ok(),
    }
}

/// The extensions `flag` takes ([`format_known`]), for messages.
pub(crate) fn extensions_of(flag: Flag) -> &'static str {
    match flag {
        Flag::DepthRaw => RawDepthFormat::EXTENSIONS,
        Flag::Depth16 => ".png",
        _ => ImageFormat::EXTENSIONS,
    }
}

/// The table, in the order the usage text lists the flags.
#[rustfmt::skip]
pub(crate) const FLAGS: &[FlagSpec] = &[
    FlagSpec { flag: Flag::Input, name: "-input", aliases: &[], values: &["FILE"], help: "scene file (6.837 assignment-1 format)" },
    FlagSpec { flag: Flag::Size, name: "-size", aliases: &[], values: &["W", "H"], help: "image size in pixels (default 200 200)" },
    FlagSpec { flag: Flag::Output, name: "-output", aliases: &[], values: &["FILE"], help: "write the colour image (.tga or .png)" },
    FlagSpec { flag: Flag::Depth, name: "-depth", aliases: &[], values: &["DMIN", "DMAX", "FILE"], help: "write the depth image: t = DMIN white … DMAX black" },
    FlagSpec { flag: Flag::DepthColourMap, name: "-depth_colormap", aliases: &[], values: &["MAP"], help: "depth image colours: {maps} (default grey)" },
    FlagSpec { flag: Flag::Depth16, name: "-depth16", aliases: &[], values: &["DMIN", "DMAX", "FILE"], help: "write the depth as a 16-bit grey PNG over DMIN … DMAX" },
    FlagSpec { flag: Flag::DepthRaw, name: "-depth_raw", aliases: &[], values: &["FILE"], help: "write raw t as 32-bit floats (.pfm or .exr), +inf = no hit" },
    FlagSpec { flag: Flag::UniformSamples, name: "-uniform_samples", aliases: &[], values: &["N"], help: "supersample on an n×n grid (N = n²)" },
    FlagSpec { flag: Flag::JitteredSamples, name: "-jittered_samples", aliases: &[], values: &["N"], help: "one random sample in each cell of an n×n grid (N = n²)" },
    FlagSpec { flag: Flag::RandomSamples, name: "-random_samples", aliases: &[], values: &["N"], help: "N random samples per pixel" },
    FlagSpec { flag: Flag::BoxFilter, name: "-box_filter", aliases: &[], values: &["R"], help: "reconstruction filter, half-width R pixels (default 0.5)" },
    FlagSpec { flag: Flag::TentFilter, name: "-tent_filter", aliases: &[], values: &["R"], help: "tent filter of radius R pixels" },
    FlagSpec { flag: Flag::GaussianFilter, name: "-gaussian_filter", aliases: &[], values: &["SIGMA"], help: "Gaussian filter, sigma in pixels (support 2·sigma)" },
    FlagSpec { flag: Flag::CompareOutput, name: "-compare_output", aliases: &[], values: &["FILE"], help: "compare a colour image (.tga/.png) with the exact one; name the mistakes" },
    FlagSpec { flag: Flag::CompareDepth, name: "-compare_depth", aliases: &[], values: &["DMIN", "DMAX", "FILE"], help: "compare a depth image made over DMIN … DMAX (inferred when left out) with the exact one" },
    FlagSpec { flag: Flag::Diff, name: "-diff", aliases: &[], values: &["FILE"], help: "write the comparison's picture: theirs, exact, heat map (.png/.tga)" },
    FlagSpec { flag: Flag::CompareFormat, name: "-compare_format", aliases: &[], values: &["lines|json"], help: "print the comparison's answer as name: value lines (default) or one JSON document (docs/compare-json.md)" },
    FlagSpec { flag: Flag::Trace, name: "-trace", aliases: &[], values: &["X", "Y"], help: "print the computation behind pixel (X, Y), Y from the bottom: ray, each sphere's roots, hit, colour, depth grey" },
    FlagSpec { flag: Flag::Stats, name: "-stats", aliases: &[], values: &[], help: "print timings and counts after rendering" },
    FlagSpec { flag: Flag::Help, name: "-help", aliases: &["--help", "-h"], values: &[], help: "print this help" },
    FlagSpec { flag: Flag::Version, name: "-version", aliases: &["--version"], values: &[], help: "print the version and the commit it was built from" },
];

impl Flag {
    /// The flag's row in the table.
    fn spec(self) -> &'static FlagSpec {
        // Every flag has a row (a unit test checks it); the first row stands in otherwise.
        FLAGS
            .iter()
            .find(|spec| spec.flag == self)
            .unwrap_or(&FLAGS[0])
    }

    /// The flag as written on the command line.
    pub fn name(self) -> &'static str {
        self.spec().name
    }

    /// How many values follow the flag.
    pub(crate) fn arity(self) -> usize {
        self.spec().values.len()
    }

    /// How many of the flag's first values may be left out together (the depth range of
    /// `-compare_depth`); they are given when the first value is a number.
    pub(crate) fn optional_lead(self) -> usize {
        match self {
            Self::CompareDepth => 2,
            _ => 0,
        }
    }

    /// The flag and its values, as the usage text and error messages show them
    /// (`-depth DMIN DMAX FILE`, `-compare_depth [DMIN DMAX] FILE`).
    pub(crate) fn synopsis(self) -> String {
        let spec = self.spec();
        let lead = self.optional_lead();
        let mut words = vec![spec.name.to_owned()];
        if lead > 0 {
            words.push(format!("[{}]", spec.values[..lead].join(" ")));
        }
        words.extend(spec.values[lead..].iter().map(|&value| value.to_owned()));
        words.join(" ")
    }

    /// The flag spelled `word` (or one of its aliases).
    pub(crate) fn named(word: &str) -> Option<Self> {
        FLAGS
            .iter()
            .find(|spec| spec.name == word || spec.aliases.contains(&word))
            .map(|spec| spec.flag)
    }
}

impl fmt::Display for Flag {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The usage text printed by `-help`.
pub fn usage() -> String {
    let input = Flag::Input.synopsis();
    let render = [Flag::Size, Flag::Output, Flag::Depth]
        .map(|flag| format!("[{}]", flag.synopsis()))
        .join(" ");
    let mut text = format!(
        "raytracer: ray-casts 6.837 assignment-1 scenes (orthographic camera, spheres)\n\n\
         usage:\n  raytracer [{input}]   open the viewer (default scene without {input_flag})\n  \
         raytracer {input} {render} [more outputs]\n      render without a window\n  \
         raytracer {GRADE_SYNOPSIS}\n      grade a class: every submission's images against the exact \
         ones, explained\n      (docs/grading.md)\n\nflags:\n",
        input_flag = Flag::Input,
    );
    for spec in FLAGS {
        let synopsis = spec.flag.synopsis();
        // A colour map's name is written once, in its own list.
        let help = spec.help.replace("{maps}", &DepthColourMap::names_listed());
        let _ = writeln!(text, "  {synopsis:<24} {help}");
    }
    let _ = write!(
        text,
        "\nexit status: 0 success (compared images match), 1 scene or file error, 2 usage error,\n\
         3 compared images differ\n\
         example:\n  raytracer {} scene1_01.txt {} 200 200 {} output1_01.tga {} 9 10 depth1_01.tga\n\
         compare your own render with the exact one, and name the mistakes behind a difference:\n  \
         raytracer {} scene1_01.txt {} mine.tga {} 9 10 mine_depth.tga {} diff.png\n",
        Flag::Input,
        Flag::Size,
        Flag::Output,
        Flag::Depth,
        Flag::Input,
        Flag::CompareOutput,
        Flag::CompareDepth,
        Flag::Diff,
    );
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: [Flag; 21] = [
        Flag::Input,
        Flag::Size,
        Flag::Output,
        Flag::Depth,
        Flag::DepthColourMap,
        Flag::Depth16,
        Flag::DepthRaw,
        Flag::UniformSamples,
        Flag::JitteredSamples,
        Flag::RandomSamples,
        Flag::BoxFilter,
        Flag::TentFilter,
        Flag::GaussianFilter,
        Flag::CompareOutput,
        Flag::CompareDepth,
        Flag::Diff,
        Flag::CompareFormat,
        Flag::Stats,
        Flag::Trace,
        Flag::Help,
        Flag::Version,
    ];

    #[test]
    fn every_flag_has_one_row_and_a_distinct_spelling() {
        assert_eq!(FLAGS.len(), ALL.len());
        for flag in ALL {
            assert_eq!(FLAGS.iter().filter(|spec| spec.flag == flag).count(), 1);
            assert_eq!(Flag::named(flag.name()), Some(flag), "{flag:?}");
        }
        let mut names: Vec<&str> = FLAGS.iter().map(|spec| spec.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), FLAGS.len());
    }

    #[test]
    fn usage_lists_every_flag_with_its_values() {
        let text = usage();
        for flag in ALL {
            assert!(text.contains(&flag.synopsis()), "{flag:?} in\n{text}");
        }
        assert!(text.contains("-depth DMIN DMAX FILE"), "{text}");
        assert!(text.contains("-compare_depth [DMIN DMAX] FILE"), "{text}");
    }
}
