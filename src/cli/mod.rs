//! The course-compatible command line, in two stages: [`RawArgs::parse`] splits the arguments
//! into known flags and their values (arity, unknown and repeated flags), then
//! [`RawArgs::validate`] turns them into a typed [`Command`] (numbers, sizes, formats).
//!
//! Flags are spelled as the course spells them, with a single dash (`-input FILE`, `-size W H`,
//! `-output FILE`, `-depth DMIN DMAX FILE`); no argument-parsing crate handles multi-value
//! single-dash flags in that style, so this is written by hand.

pub mod progress;
pub mod run;

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::path::PathBuf;

use crate::output::ImageFormat;
use crate::output::depth_file::RawDepthFormat;
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::sampling::SamplingError;
use crate::render::{
    Filter, MAX_PIXELS, MAX_SIDE_PX, Precision, Quality, Sampler, Sampling, check_image_size,
};

/// One flag: its spelling, how many values follow it, and its line in the usage text.
struct FlagSpec {
    name: &'static str,
    values: usize,
    usage: &'static str,
}

const FLAGS: &[FlagSpec] = &[
    FlagSpec {
        name: "-input",
        values: 1,
        usage: "-input FILE              scene file (6.837 assignment-1 format)",
    },
    FlagSpec {
        name: "-size",
        values: 2,
        usage: "-size W H                image size in pixels (default 200 200)",
    },
    FlagSpec {
        name: "-output",
        values: 1,
        usage: "-output FILE             write the colour image (.tga or .png)",
    },
    FlagSpec {
        name: "-depth",
        values: 3,
        usage: "-depth DMIN DMAX FILE    write the depth image: t = DMIN white … DMAX black",
    },
    FlagSpec {
        name: "-depth_colormap",
        values: 1,
        usage: "-depth_colormap MAP      depth image colours: grey (default), turbo or viridis",
    },
    FlagSpec {
        name: "-depth16",
        values: 3,
        usage: "-depth16 DMIN DMAX FILE  write the depth as a 16-bit grey PNG over DMIN … DMAX",
    },
    FlagSpec {
        name: "-depth_raw",
        values: 1,
        usage: "-depth_raw FILE          write raw t as 32-bit floats (.pfm or .exr), +inf = no hit",
    },
    FlagSpec {
        name: "-precision",
        values: 1,
        usage: "-precision f64|f32|auto  per-pixel arithmetic (default f64: exact)",
    },
    FlagSpec {
        name: "-uniform_samples",
        values: 1,
        usage: "-uniform_samples N       supersample on an n×n grid (N = n²)",
    },
    FlagSpec {
        name: "-jittered_samples",
        values: 1,
        usage: "-jittered_samples N      one random sample in each cell of an n×n grid (N = n²)",
    },
    FlagSpec {
        name: "-random_samples",
        values: 1,
        usage: "-random_samples N        N random samples per pixel",
    },
    FlagSpec {
        name: "-box_filter",
        values: 1,
        usage: "-box_filter R            reconstruction filter, half-width R pixels (default 0.5)",
    },
    FlagSpec {
        name: "-tent_filter",
        values: 1,
        usage: "-tent_filter R           tent filter of radius R pixels",
    },
    FlagSpec {
        name: "-gaussian_filter",
        values: 1,
        usage: "-gaussian_filter SIGMA   Gaussian filter, sigma in pixels (support 2·sigma)",
    },
    FlagSpec {
        name: "-stats",
        values: 0,
        usage: "-stats                   print timings and counts after rendering",
    },
    FlagSpec {
        name: "-help",
        values: 0,
        usage: "-help                    print this help",
    },
];

fn flag_spec(name: &str) -> Option<&'static FlagSpec> {
    FLAGS.iter().find(|flag| flag.name == name)
}

/// Image size used when `-size` is not given: the course's 200 × 200.
pub const DEFAULT_SIZE_PX: (u32, u32) = (200, 200);

/// The usage text printed by `-help`.
pub fn usage() -> String {
    let mut text = String::from(
        "raytracer: ray-casts 6.837 assignment-1 scenes (orthographic camera, spheres)\n\n\
         usage:\n  raytracer [-input FILE]                     open the viewer (default scene without -input)\n  \
         raytracer -input FILE [-size W H] [-output FILE] [-depth DMIN DMAX FILE] [more outputs]\n                                              render without a window\n\nflags:\n",
    );
    for flag in FLAGS {
        text.push_str("  ");
        text.push_str(flag.usage);
        text.push('\n');
    }
    text.push_str(
        "\nexit status: 0 success, 1 scene or file error, 2 usage error\n\
         example:\n  raytracer -input scene1_01.txt -size 200 200 -output output1_01.tga -depth 9 10 depth1_01.tga\n",
    );
    text
}

/// A command-line mistake; the program prints it and exits with status 2.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UsageError {
    /// A flag the program does not know.
    #[error("unknown flag '{0}' (raytracer -help lists the flags)")]
    UnknownFlag(String),
    /// A word that is not a flag where a flag was expected.
    #[error(
        "unexpected argument '{0}': expected a flag such as -input (raytracer -help lists them)"
    )]
    StrayArgument(String),
    /// A flag given twice.
    #[error("flag {0} is given twice")]
    Repeated(&'static str),
    /// Too few values after a flag.
    #[error("flag {flag} needs {needed} value(s): {usage}")]
    MissingValue {
        /// The flag.
        flag: &'static str,
        /// How many it needs.
        needed: usize,
        /// Its usage line.
        usage: &'static str,
    },
    /// A value that should be a number is not one.
    #[error("{flag}: expected {what}, found '{found}'")]
    BadNumber {
        /// The flag.
        flag: &'static str,
        /// What kind of number.
        what: &'static str,
        /// The value as given.
        found: String,
    },
    /// An image size outside the supported range.
    #[error(
        "-size: {width_px}×{height_px} is out of range: each side 1..={MAX_SIDE_PX}, \
         at most {MAX_PIXELS} pixels in all"
    )]
    BadSize {
        /// Requested width.
        width_px: u64,
        /// Requested height.
        height_px: u64,
    },
    /// An output whose extension names no supported format.
    #[error(
        "{flag}: '{path}' has an unknown format; use one of {}",
        match *flag {
            "-depth_raw" => RawDepthFormat::EXTENSIONS,
            "-depth16" => ".png",
            _ => ImageFormat::EXTENSIONS,
        }
    )]
    UnknownFormat {
        /// The flag.
        flag: &'static str,
        /// The path as given.
        path: String,
    },
    /// Two outputs name the same file.
    #[error("two outputs name the same file '{0}'")]
    SameOutput(String),
    /// A depth colour map that does not exist.
    #[error("-depth_colormap: expected grey, turbo or viridis, found '{0}'")]
    BadColourMap(String),
    /// An argument that is not valid Unicode where text is needed.
    #[error("{flag}: value is not valid text")]
    NotText {
        /// The flag.
        flag: &'static str,
    },
    /// Rendering needs a scene.
    #[error("-output, -depth, -depth16 and -depth_raw need -input FILE")]
    MissingInput,
    /// A precision that is not f64, f32 or auto.
    #[error("-precision: expected f64, f32 or auto, found '{0}'")]
    BadPrecision(String),
    /// Two flags that exclude each other.
    #[error("{0} and {1} exclude each other: give one")]
    Conflicting(&'static str, &'static str),
    /// Unusable sampling settings.
    #[error("{0}")]
    BadSampling(#[from] SamplingError),
}

/// The depth image to write.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthOutput {
    /// t range mapped white … black.
    pub range: DepthRange,
    /// Where to write it.
    pub path: PathBuf,
}

/// A headless render: what to read, how large, what to write.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderRequest {
    /// Scene file.
    pub input: PathBuf,
    /// Image width in pixels.
    pub width_px: u32,
    /// Image height in pixels.
    pub height_px: u32,
    /// Colour image destination.
    pub colour_output: Option<PathBuf>,
    /// Depth image destination and range.
    pub depth_output: Option<DepthOutput>,
    /// Colour map of the depth image (`-depth_colormap`; grey by default).
    pub depth_colour_map: DepthColourMap,
    /// 16-bit grey depth PNG destination and range (`-depth16`).
    pub depth16_output: Option<DepthOutput>,
    /// Raw t destination (`-depth_raw`, `.pfm` or `.exr`).
    pub depth_raw_output: Option<PathBuf>,
    /// Precision and other quality knobs.
    pub quality: Quality,
    /// Print timings and counts after rendering.
    pub stats: bool,
}

/// Opening the viewer.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ViewerRequest {
    /// Scene file; the embedded default scene when `None`.
    pub input: Option<PathBuf>,
    /// `-size W H`, if given: the export size the viewer starts with.
    pub size_px: Option<(u32, u32)>,
    /// `-precision`, if given: the viewer's precision mode.
    pub precision: Option<Precision>,
}

/// What the command line asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Print the usage text.
    Help,
    /// Render without a window.
    Render(RenderRequest),
    /// Open the viewer.
    View(ViewerRequest),
}

/// Stage one: flags recognised, values collected, nothing interpreted.
#[derive(Debug, Clone, Default)]
pub struct RawArgs {
    values: BTreeMap<&'static str, Vec<OsString>>,
}

impl RawArgs {
    /// Splits arguments (without the program name) into flags and values.
    pub fn parse<I, S>(arguments: I) -> Result<Self, UsageError>
    where
        I: IntoIterator<Item = S>,
        S: Into<OsString>,
    {
        let mut arguments = arguments.into_iter().map(Into::into).peekable();
        let mut values = BTreeMap::new();
        while let Some(argument) = arguments.next() {
            let text = argument.to_string_lossy();
            let name = match text.as_ref() {
                "--help" | "-h" => "-help",
                name => name,
            };
            let spec = match flag_spec(name) {
                Some(spec) => spec,
                None if name.starts_with('-') && name.len() > 1 => {
                    return Err(UsageError::UnknownFlag(name.to_owned()));
                }
                None => return Err(UsageError::StrayArgument(name.to_owned())),
            };
            let mut flag_values = Vec::with_capacity(spec.values);
            for _ in 0..spec.values {
                // A value may start with '-' (a negative depth); a known flag may not be a value.
                let is_flag = arguments
                    .peek()
                    .is_some_and(|next| flag_spec(&next.to_string_lossy()).is_some());
                match arguments.next() {
                    Some(value) if !is_flag => flag_values.push(value),
                    _ => {
                        return Err(UsageError::MissingValue {
                            flag: spec.name,
                            needed: spec.values,
                            usage: spec.usage,
                        });
                    }
                }
            }
            if values.insert(spec.name, flag_values).is_some() {
                return Err(UsageError::Repeated(spec.name));
            }
        }
        Ok(Self { values })
    }

    /// Stage two: interprets the values into a typed [`Command`].
    pub fn validate(&self) -> Result<Command, UsageError> {
        if self.values.contains_key("-help") {
            return Ok(Command::Help);
        }
        let input = self.value("-input", 0).map(PathBuf::from);
        let size_px = match self.values.get("-size") {
            Some(_) => Some(self.size()?),
            None => None,
        };
        let colour_output = self.output_path("-output", 0)?;
        let depth_output = self.depth_output("-depth")?;
        let depth16_output = self.depth_output("-depth16")?;
        let depth_raw_output = self.output_path("-depth_raw", 0)?;
        let outputs: Vec<&PathBuf> = colour_output
            .iter()
            .chain(depth_output.iter().map(|d| &d.path))
            .chain(depth16_output.iter().map(|d| &d.path))
            .chain(depth_raw_output.iter())
            .collect();
        for (index, path) in outputs.iter().enumerate() {
            if outputs[..index].contains(path) {
                return Err(UsageError::SameOutput(path.display().to_string()));
            }
        }
        let depth_colour_map = match self.values.get("-depth_colormap") {
            Some(_) => {
                let text = self.text("-depth_colormap", 0)?;
                DepthColourMap::from_name(text)
                    .ok_or_else(|| UsageError::BadColourMap(text.to_owned()))?
            }
            None => DepthColourMap::Grey,
        };
        let precision = match self.values.get("-precision") {
            Some(_) => {
                let text = self.text("-precision", 0)?;
                Some(
                    text.parse::<Precision>()
                        .map_err(|_| UsageError::BadPrecision(text.to_owned()))?,
                )
            }
            None => None,
        };
        if outputs.is_empty() {
            return Ok(Command::View(ViewerRequest {
                input,
                size_px,
                precision,
            }));
        }
        let input = input.ok_or(UsageError::MissingInput)?;
        let (width_px, height_px) = size_px.unwrap_or(DEFAULT_SIZE_PX);
        Ok(Command::Render(RenderRequest {
            input,
            width_px,
            height_px,
            colour_output,
            depth_output,
            depth_colour_map,
            depth16_output,
            depth_raw_output,
            quality: Quality {
                precision: precision.unwrap_or_default(),
                sampling: self.sampling()?,
            },
            stats: self.values.contains_key("-stats"),
        }))
    }

    /// The one flag of `names` that is given, if any; two of them are a conflict.
    fn one_of(&self, names: &[&'static str]) -> Result<Option<&'static str>, UsageError> {
        let given: Vec<&'static str> = names
            .iter()
            .copied()
            .filter(|name| self.values.contains_key(name))
            .collect();
        match given.as_slice() {
            [] => Ok(None),
            [one] => Ok(Some(one)),
            [first, second, ..] => Err(UsageError::Conflicting(first, second)),
        }
    }

    /// Supersampling from the course's sampler and filter flags; `None` without either.
    fn sampling(&self) -> Result<Option<Sampling>, UsageError> {
        let sampler_flag =
            self.one_of(&["-uniform_samples", "-jittered_samples", "-random_samples"])?;
        let filter_flag = self.one_of(&["-box_filter", "-tent_filter", "-gaussian_filter"])?;
        if sampler_flag.is_none() && filter_flag.is_none() {
            return Ok(None);
        }
        let (sampler, samples) = match sampler_flag {
            Some(flag) => {
                let text = self.text(flag, 0)?;
                let samples = text.parse::<u32>().map_err(|_| UsageError::BadNumber {
                    flag,
                    what: "a whole number of samples",
                    found: text.to_owned(),
                })?;
                let sampler = match flag {
                    "-uniform_samples" => Sampler::Uniform,
                    "-jittered_samples" => Sampler::Jittered,
                    _ => Sampler::Random,
                };
                (sampler, samples)
            }
            None => (Sampler::Uniform, 1),
        };
        let filter = match filter_flag {
            Some(flag) => {
                let size = self.finite(flag, 0, "a size in pixels")? as f32;
                match flag {
                    "-box_filter" => Filter::Box { radius: size },
                    "-tent_filter" => Filter::Tent { radius: size },
                    _ => Filter::Gaussian { sigma: size },
                }
            }
            None => Filter::PIXEL_BOX,
        };
        let sampling = Sampling {
            sampler,
            samples,
            filter,
            seed: 0,
        };
        sampling.validate()?;
        Ok(Some(sampling))
    }

    fn value(&self, flag: &str, index: usize) -> Option<&OsString> {
        self.values.get(flag).and_then(|values| values.get(index))
    }

    fn text(&self, flag: &'static str, index: usize) -> Result<&str, UsageError> {
        self.value(flag, index)
            .map(|value| value.to_str().ok_or(UsageError::NotText { flag }))
            .unwrap_or(Ok(""))
    }

    fn finite(
        &self,
        flag: &'static str,
        index: usize,
        what: &'static str,
    ) -> Result<f64, UsageError> {
        let text = self.text(flag, index)?;
        match text.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            _ => Err(UsageError::BadNumber {
                flag,
                what,
                found: text.to_owned(),
            }),
        }
    }

    fn size(&self) -> Result<(u32, u32), UsageError> {
        let side = |index, what| {
            let text = self.text("-size", index)?;
            text.parse::<u64>().map_err(|_| UsageError::BadNumber {
                flag: "-size",
                what,
                found: text.to_owned(),
            })
        };
        let (width_px, height_px) = (
            side(0, "a whole number of pixels (W)")?,
            side(1, "a whole number of pixels (H)")?,
        );
        let bad = UsageError::BadSize {
            width_px,
            height_px,
        };
        let (Ok(width), Ok(height)) = (u32::try_from(width_px), u32::try_from(height_px)) else {
            return Err(bad);
        };
        check_image_size(width, height).map_err(|_| bad)?;
        Ok((width, height))
    }

    /// A `-depth`-style output: DMIN DMAX FILE.
    fn depth_output(&self, flag: &'static str) -> Result<Option<DepthOutput>, UsageError> {
        if !self.values.contains_key(flag) {
            return Ok(None);
        }
        Ok(Some(DepthOutput {
            range: DepthRange::new(
                self.finite(flag, 0, "a number (DMIN)")?,
                self.finite(flag, 1, "a number (DMAX)")?,
            ),
            path: self.output_path(flag, 2)?.unwrap_or_default(),
        }))
    }

    /// An output path whose extension names a format the flag writes.
    fn output_path(&self, flag: &'static str, index: usize) -> Result<Option<PathBuf>, UsageError> {
        let Some(value) = self.value(flag, index) else {
            return Ok(None);
        };
        let path = PathBuf::from(value);
        let known = match flag {
            "-depth_raw" => RawDepthFormat::from_path(&path).is_some(),
            "-depth16" => matches!(ImageFormat::from_path(&path), Ok(ImageFormat::Png)),
            _ => ImageFormat::from_path(&path).is_ok(),
        };
        if !known {
            return Err(UsageError::UnknownFormat {
                flag,
                path: path.display().to_string(),
            });
        }
        Ok(Some(path))
    }
}

/// Both stages: arguments (without the program name) → [`Command`].
pub fn parse_command<I, S>(arguments: I) -> Result<Command, UsageError>
where
    I: IntoIterator<Item = S>,
    S: Into<OsString>,
{
    RawArgs::parse(arguments)?.validate()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(line: &str) -> Result<Command, UsageError> {
        parse_command(line.split_whitespace())
    }

    #[test]
    fn course_command_line_gives_a_render_request() {
        let command =
            parse("-input scene1_01.txt -size 200 100 -output out.tga -depth 9 10 depth.tga")
                .unwrap();
        assert_eq!(
            command,
            Command::Render(RenderRequest {
                input: "scene1_01.txt".into(),
                width_px: 200,
                height_px: 100,
                colour_output: Some("out.tga".into()),
                depth_output: Some(DepthOutput {
                    range: DepthRange::new(9.0, 10.0),
                    path: "depth.tga".into()
                }),
                depth_colour_map: DepthColourMap::Grey,
                depth16_output: None,
                depth_raw_output: None,
                quality: Quality::default(),
                stats: false,
            })
        );
    }

    #[test]
    fn negative_depth_values_are_values_not_flags() {
        let Command::Render(request) = parse("-input a.txt -depth -2 2 d.png").unwrap() else {
            panic!("expected a render request");
        };
        assert_eq!(
            request.depth_output.unwrap().range,
            DepthRange::new(-2.0, 2.0)
        );
        assert_eq!((request.width_px, request.height_px), DEFAULT_SIZE_PX);
    }

    #[test]
    fn precision_flag_selects_the_mode() {
        let Command::Render(request) = parse("-input a.txt -output x.png -precision auto").unwrap()
        else {
            panic!("expected a render request");
        };
        assert_eq!(request.quality.precision, Precision::Auto);
    }

    #[test]
    fn course_sampling_flags_give_a_sampling() {
        let Command::Render(request) =
            parse("-input a.txt -output x.png -jittered_samples 16 -gaussian_filter 0.8 -stats")
                .unwrap()
        else {
            panic!("expected a render request");
        };
        let sampling = request.quality.sampling.unwrap();
        assert_eq!(sampling.sampler, Sampler::Jittered);
        assert_eq!(sampling.samples, 16);
        assert_eq!(sampling.filter, Filter::Gaussian { sigma: 0.8 });
        assert!(request.stats);
        let Command::Render(request) = parse("-input a.txt -output x.png").unwrap() else {
            panic!("expected a render request");
        };
        assert_eq!(
            request.quality.sampling, None,
            "no flags: one centre sample"
        );
    }

    #[test]
    fn without_outputs_the_viewer_opens() {
        assert_eq!(parse("").unwrap(), Command::View(ViewerRequest::default()));
        assert_eq!(
            parse("-input a.txt -size 640 480").unwrap(),
            Command::View(ViewerRequest {
                input: Some("a.txt".into()),
                size_px: Some((640, 480)),
                precision: None,
            })
        );
        assert_eq!(parse("-help").unwrap(), Command::Help);
        assert_eq!(parse("--help").unwrap(), Command::Help);
    }

    #[test]
    fn mistakes_are_usage_errors() {
        let cases = [
            ("-inptu a.txt", "unknown flag '-inptu'"),
            ("a.txt", "unexpected argument 'a.txt'"),
            ("-input", "-input needs 1 value"),
            ("-input a.txt -size 200", "-size needs 2 value"),
            (
                "-input a.txt -size 200 -output x.tga",
                "-size needs 2 value",
            ),
            ("-input a.txt -size 0 200 -output x.tga", "out of range"),
            ("-input a.txt -size 20000 200 -output x.tga", "out of range"),
            (
                "-input a.txt -size 99999999999 200 -output x.tga",
                "out of range",
            ),
            (
                "-input a.txt -size -5 200 -output x.tga",
                "expected a whole number",
            ),
            (
                "-input a.txt -size 2.5 200 -output x.tga",
                "expected a whole number",
            ),
            (
                "-input a.txt -depth a 1 d.tga",
                "expected a number (DMIN), found 'a'",
            ),
            (
                "-input a.txt -depth 1 inf d.tga",
                "expected a number (DMAX), found 'inf'",
            ),
            ("-input a.txt -output x.jpg", "unknown format"),
            ("-input a.txt -depth_raw x.png", "use one of .pfm, .exr"),
            ("-input a.txt -depth16 0 1 x.tga", "use one of .png"),
            ("-input a.txt -output x.png -depth16 0 1 x.png", "same file"),
            (
                "-input a.txt -depth_raw d.pfm -depth_colormap jet",
                "expected grey, turbo or viridis, found 'jet'",
            ),
            ("-input a.txt -output x.tga -output y.tga", "given twice"),
            ("-input a.txt -output x.tga -depth 1 2 x.tga", "same file"),
            ("-output x.tga", "need -input"),
            (
                "-input a.txt -output x.tga -precision f16",
                "expected f64, f32 or auto, found 'f16'",
            ),
        ];
        for (line, message) in cases {
            let error = parse(line).expect_err(line).to_string();
            assert!(error.contains(message), "{line}: {error}");
        }
    }

    #[test]
    fn depth_outputs_and_colour_map() {
        let Command::Render(request) =
            parse("-input a.txt -depth_raw t.exr -depth16 -1 2.5 d16.png -depth_colormap viridis")
                .unwrap()
        else {
            panic!("a render request");
        };
        assert_eq!(request.depth_raw_output, Some("t.exr".into()));
        assert_eq!(
            request.depth16_output,
            Some(DepthOutput {
                range: DepthRange::new(-1.0, 2.5),
                path: "d16.png".into()
            })
        );
        assert_eq!(request.depth_colour_map, DepthColourMap::Viridis);
        assert!(request.colour_output.is_none() && request.depth_output.is_none());
    }

    #[test]
    fn usage_lists_every_flag() {
        let text = usage();
        for flag in FLAGS {
            assert!(text.contains(flag.name));
        }
    }
}
