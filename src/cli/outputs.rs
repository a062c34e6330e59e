//! The files a render request writes, each named by its own flag (`-output`, `-depth`,
//! `-depth16`, `-depth_raw`): the one list of them. The check that no two name one file, the
//! arguments written back, the streamed path's choice and the grader's refusal all walk
//! [`Outputs::each`]. A new output flag is its rows in the flag table (`flags.rs`: the flag,
//! `OUTPUT_FLAGS`, its formats), a field and its arms here, and how `run.rs` makes its file.

use std::path::{Path, PathBuf};

use super::error::UsageError;
use super::flags::{Flag, OUTPUT_FLAGS};
use super::raw_args::RawArgs;
use crate::render::depth_map::DepthRange;

/// A depth image to write.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthOutput {
    /// t range mapped white … black.
    pub(crate) range: DepthRange,
    /// Where to write it.
    pub(crate) path: PathBuf,
}

/// Every file a request writes (the comparison's `-diff` picture is the comparison's).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Outputs {
    /// Colour image (`-output`).
    pub(crate) colour: Option<PathBuf>,
    /// Depth image and its range (`-depth`).
    pub(crate) depth: Option<DepthOutput>,
    /// 16-bit grey depth PNG and its range (`-depth16`).
    pub(crate) depth16: Option<DepthOutput>,
    /// Raw t (`-depth_raw`, `.pfm` or `.exr`).
    pub(crate) depth_raw: Option<PathBuf>,
}

/// One output of a request: its flag, its file, and the depth range it maps when it takes one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Output<'a> {
    pub(crate) flag: Flag,
    pub(crate) path: &'a Path,
    pub(crate) range: Option<DepthRange>,
}

impl Outputs {
    /// The output `flag` names, if the request has it.
    fn get(&self, flag: Flag) -> Option<Output<'_>> {
        fn plain(flag: Flag, path: &Option<PathBuf>) -> Option<Output<'_>> {
            path.as_deref().map(|path| Output {
                flag,
                path,
                range: None,
            })
        }
        fn ranged(flag: Flag, depth: &Option<DepthOutput>) -> Option<Output<'_>> {
            depth.as_ref().map(|depth| Output {
                flag,
                path: &depth.path,
                range: Some(depth.range),
            })
        }
        match flag {
            Flag::Output => plain(flag, &self.colour),
            Flag::Depth => ranged(flag, &self.depth),
            Flag::Depth16 => ranged(flag, &self.depth16),
            Flag::DepthRaw => plain(flag, &self.depth_raw),
            _ => None,
        }
    }

    /// Every output the request has, in the order of [`OUTPUT_FLAGS`].
    pub(crate) fn each(&self) -> Vec<Output<'_>> {
        OUTPUT_FLAGS
            .iter()
            .filter_map(|flag| self.get(*flag))
            .collect()
    }

    /// The depth range of the first output that maps one (`-depth`, else `-depth16`).
    pub(crate) fn depth_range(&self) -> Option<DepthRange> {
        self.each().iter().find_map(|output| output.range)
    }
}

impl RawArgs {
    /// The outputs the arguments name, each path's format checked.
    pub(super) fn outputs(&self) -> Result<Outputs, UsageError> {
        Ok(Outputs {
            colour: self.output_path(Flag::Output, 0)?,
            depth: self.depth_output(Flag::Depth)?,
            depth16: self.depth_output(Flag::Depth16)?,
            depth_raw: self.output_path(Flag::DepthRaw, 0)?,
        })
    }
}
