//! Stage two of parsing: [`RawArgs`] interpreted into a typed [`Command`] (numbers, sizes,
//! formats). The way back, [`RenderRequest::to_arguments`], is in `to_arguments.rs`.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use super::error::UsageError;
use super::flags::Flag;
use super::flags::GRADE_WORD;
use super::flags::format_known;
use super::grade_request::{GradeRequest, parse_grade};
use super::outputs::{DepthOutput, Outputs};
use super::raw_args::RawArgs;
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::{Filter, Quality, Sampler, Sampling, check_image_size};

/// Image size used when `-size` is not given: the course's 200 × 200.
pub const DEFAULT_SIZE_PX: (u32, u32) = (200, 200);

/// The sampler flags and the sampler each chooses.
pub(super) const SAMPLER_FLAGS: [(Flag, Sampler); 3] = [
    (Flag::UniformSamples, Sampler::Uniform),
    (Flag::JitteredSamples, Sampler::Jittered),
    (Flag::RandomSamples, Sampler::Random),
];

/// Makes a filter of a size in pixels.
type MakeFilter = fn(f32) -> Filter;

/// The filter flags and the filter each chooses (of a size in pixels).
pub(super) const FILTER_FLAGS: [(Flag, MakeFilter); 3] = [
    (Flag::BoxFilter, |radius| Filter::Box { radius }),
    (Flag::TentFilter, |radius| Filter::Tent { radius }),
    (Flag::GaussianFilter, |sigma| Filter::Gaussian { sigma }),
];

/// Their depth image to compare, and the range it was made over when given.
#[derive(Debug, Clone, PartialEq)]
pub struct TheirDepth {
    /// t range mapped white … black; `None`: inferred from the image.
    pub(crate) range: Option<DepthRange>,
    /// The image.
    pub(crate) path: PathBuf,
}

/// Images to compare with the exact render (`-compare_output`, `-compare_depth`) and where to
/// write the difference picture (`-diff`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompareRequest {
    /// Their colour image.
    pub(crate) colour: Option<PathBuf>,
    /// Their depth image and the range it was made over.
    pub(crate) depth: Option<TheirDepth>,
    /// The difference picture's destination.
    pub(crate) diff: Option<PathBuf>,
    /// The answer as one JSON document instead of `name: value` lines.
    pub(crate) json: bool,
}

impl RenderRequest {
    /// Whether the comparison's answer is printed as JSON (`-compare_format json`).
    pub fn answer_as_json(&self) -> bool {
        self.compare.as_ref().is_some_and(|c| c.json)
    }
}

/// A headless render: what to read, how large, what to write.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderRequest {
    /// Scene file.
    pub(crate) input: PathBuf,
    /// Image width in pixels.
    pub(crate) width_px: u32,
    /// Image height in pixels.
    pub(crate) height_px: u32,
    /// Whether `-size` was given (else the size is the course's 200×200, or that of the images
    /// compared).
    pub(crate) size_given: bool,
    /// Images to compare with the exact render.
    pub(crate) compare: Option<CompareRequest>,
    /// The files it writes.
    pub(crate) outputs: Outputs,
    /// Colour map of the depth image (`-depth_colormap`; grey by default).
    pub(crate) depth_colour_map: DepthColourMap,
    /// Quality: samples per pixel.
    pub(crate) quality: Quality,
    /// Print timings and counts after rendering.
    pub stats: bool,
    /// `-trace X Y`: print the computation behind this pixel (x, y from the bottom).
    pub(crate) trace: Option<(u32, u32)>,
}

/// Opening the viewer.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ViewerRequest {
    /// Scene file; the embedded default scene when `None`.
    pub input: Option<PathBuf>,
    /// `-size W H`, if given: the export size the viewer starts with.
    pub size_px: Option<(u32, u32)>,
    /// The `raytracer` binary itself (absolute), which export scripts run; set by the binary,
    /// not by a flag.
    pub program: Option<PathBuf>,
}

/// What the command line asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Print the usage text.
    Help,
    /// Print the version line.
    Version,
    /// Render without a window.
    Render(Box<RenderRequest>),
    /// Open the viewer.
    View(ViewerRequest),
    /// Grade a class's images against the exact ones (`raytracer grade …`).
    Grade(GradeRequest),
}

/// Both stages: arguments (without the program name) → [`Command`].
pub fn parse_command<I, S>(arguments: I) -> Result<Command, UsageError>
where
    I: IntoIterator<Item = S>,
    S: Into<OsString>,
{
    let arguments: Vec<OsString> = arguments.into_iter().map(Into::into).collect();
    if arguments.first().is_some_and(|word| word == GRADE_WORD) {
        return parse_grade(&arguments[1..]).map(Command::Grade);
    }
    RawArgs::parse(arguments)?.validate()
}

impl RawArgs {
    /// Stage two: interprets the values into a typed [`Command`].
    pub(crate) fn validate(&self) -> Result<Command, UsageError> {
        if self.has(Flag::Help) {
            return Ok(Command::Help);
        }
        if self.has(Flag::Version) {
            return Ok(Command::Version);
        }
        let input = self.value(Flag::Input, 0).map(PathBuf::from);
        if input
            .as_ref()
            .is_some_and(|path| path.as_os_str().is_empty())
        {
            return Err(UsageError::EmptyPath(Flag::Input));
        }
        let size_px = if self.has(Flag::Size) {
            Some(self.size()?)
        } else {
            None
        };
        let outputs = self.outputs()?;
        let compare = self.compare()?;
        let written: Vec<&Path> = outputs
            .each()
            .iter()
            .map(|output| output.path)
            .chain(compare.iter().filter_map(|c| c.diff.as_deref()))
            .collect();
        for (index, path) in written.iter().enumerate() {
            if written[..index].contains(path) {
                return Err(UsageError::SameOutput(path.display().to_string()));
            }
        }
        let depth_colour_map = if self.has(Flag::DepthColourMap) {
            let text = self.text(Flag::DepthColourMap, 0)?;
            DepthColourMap::from_name(text)
                .ok_or_else(|| UsageError::BadColourMap(text.to_owned()))?
        } else {
            DepthColourMap::Grey
        };
        let trace = self.trace()?;
        if written.is_empty() && compare.is_none() && trace.is_none() {
            return Ok(Command::View(ViewerRequest {
                input,
                size_px,
                program: None,
            }));
        }
        let input = input.ok_or(UsageError::MissingInput)?;
        let (width_px, height_px) = size_px.unwrap_or(DEFAULT_SIZE_PX);
        Ok(Command::Render(Box::new(RenderRequest {
            input,
            width_px,
            height_px,
            size_given: size_px.is_some(),
            compare,
            outputs,
            depth_colour_map,
            quality: Quality {
                sampling: self.sampling()?,
            },
            stats: self.has(Flag::Stats),
            trace,
        })))
    }

    /// The comparison flags; `None` without `-compare_output` and `-compare_depth`.
    fn compare(&self) -> Result<Option<CompareRequest>, UsageError> {
        let colour = self.output_path(Flag::CompareOutput, 0)?;
        let depth = self.their_depth()?;
        let diff = self.output_path(Flag::Diff, 0)?;
        let json = if self.has(Flag::CompareFormat) {
            match self.text(Flag::CompareFormat, 0)? {
                "json" => true,
                "lines" => false,
                other => return Err(UsageError::BadCompareFormat(other.to_owned())),
            }
        } else {
            false
        };
        if colour.is_none() && depth.is_none() {
            return if diff.is_some() {
                Err(UsageError::DiffWithoutComparison)
            } else if self.has(Flag::CompareFormat) {
                Err(UsageError::FormatWithoutComparison)
            } else {
                Ok(None)
            };
        }
        if let (Some(colour), Some(depth)) = (&colour, &depth)
            && *colour == depth.path
        {
            return Err(UsageError::SameOutput(colour.display().to_string()));
        }
        Ok(Some(CompareRequest {
            colour,
            depth,
            diff,
            json,
        }))
    }

    /// Supersampling from the course's sampler and filter flags; `None` without either.
    fn sampling(&self) -> Result<Option<Sampling>, UsageError> {
        let sampler_flag = self.one_of(&SAMPLER_FLAGS.map(|(flag, _)| flag))?;
        let filter_flag = self.one_of(&FILTER_FLAGS.map(|(flag, _)| flag))?;
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
                let sampler = SAMPLER_FLAGS
                    .iter()
                    .find(|(f, _)| *f == flag)
                    .map_or(Sampler::Uniform, |(_, sampler)| *sampler);
                (sampler, samples)
            }
            None => (Sampler::Uniform, 1),
        };
        let filter = match filter_flag {
            Some(flag) => {
                let text = self.text(flag, 0)?;
                let bad = |what| UsageError::BadNumber {
                    flag,
                    what,
                    found: text.to_owned(),
                };
                let wide = text
                    .parse::<f64>()
                    .ok()
                    .filter(|size| size.is_finite())
                    .ok_or_else(|| bad("a size in pixels"))?;
                // Sizes are kept in 32 bits: one that would become 0 there is refused as given.
                let size = wide as f32;
                if wide > 0.0 && size == 0.0 {
                    return Err(bad("a size in pixels of at least 1e-38"));
                }
                let make = FILTER_FLAGS
                    .iter()
                    .find(|(f, _)| *f == flag)
                    .map_or(FILTER_FLAGS[0].1, |(_, make)| *make);
                make(size)
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

    fn finite(&self, flag: Flag, index: usize, what: &'static str) -> Result<f64, UsageError> {
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

    /// `-trace X Y`, if given (checked against the image size when the run knows it).
    fn trace(&self) -> Result<Option<(u32, u32)>, UsageError> {
        if !self.has(Flag::Trace) {
            return Ok(None);
        }
        let coordinate = |index, what| {
            let text = self.text(Flag::Trace, index)?;
            text.parse::<u32>().map_err(|_| UsageError::BadNumber {
                flag: Flag::Trace,
                what,
                found: text.to_owned(),
            })
        };
        Ok(Some((
            coordinate(0, "a pixel column from 0 (X)")?,
            coordinate(1, "a pixel row from 0 at the bottom (Y)")?,
        )))
    }

    fn size(&self) -> Result<(u32, u32), UsageError> {
        let side = |index, what| {
            let text = self.text(Flag::Size, index)?;
            text.parse::<u64>().map_err(|_| UsageError::BadNumber {
                flag: Flag::Size,
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
    pub(super) fn depth_output(&self, flag: Flag) -> Result<Option<DepthOutput>, UsageError> {
        if !self.has(flag) {
            return Ok(None);
        }
        let (min_t, max_t) = (
            self.finite(flag, 0, "a number (DMIN)")?,
            self.finite(flag, 1, "a number (DMAX)")?,
        );
        if !(max_t - min_t).is_finite() {
            return Err(UsageError::DepthRangeTooWide(flag));
        }
        Ok(Some(DepthOutput {
            range: DepthRange::new(min_t, max_t),
            path: self.output_path(flag, 2)?.unwrap_or_default(),
        }))
    }

    /// `-compare_depth [DMIN DMAX] FILE`.
    fn their_depth(&self) -> Result<Option<TheirDepth>, UsageError> {
        let flag = Flag::CompareDepth;
        match self.count(flag) {
            0 => Ok(None),
            1 => Ok(Some(TheirDepth {
                range: None,
                path: self.output_path(flag, 0)?.unwrap_or_default(),
            })),
            _ => Ok(self.depth_output(flag)?.map(|depth| TheirDepth {
                range: Some(depth.range),
                path: depth.path,
            })),
        }
    }

    /// An output path whose extension names a format the flag writes.
    pub(super) fn output_path(
        &self,
        flag: Flag,
        index: usize,
    ) -> Result<Option<PathBuf>, UsageError> {
        let Some(value) = self.value(flag, index) else {
            return Ok(None);
        };
        let path = PathBuf::from(value);
        if !format_known(flag, &path) {
            return Err(UsageError::UnknownFormat {
                flag,
                path: path.display().to_string(),
            });
        }
        Ok(Some(path))
    }
}
