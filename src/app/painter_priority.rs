//! The window's painter gives way to the renderer. Without a GPU, Mesa paints the window on the
//! CPU, on threads of its own (`llvmpipe-N`, one per core, for OpenGL and for wgpu alike), and
//! they compete for the cores with rayon's threads drawing the next frame: a frame in the window
//! took 2.4–2.9× its benchmark where the painter had the renderer's priority.
//!
//! So once the window is up, the viewer raises the nice value of Mesa's painter threads (by
//! [`DEFAULT_PAINTER_NICE`], or what `RAYTRACER_PAINTER_NICE` says, 0 to leave them as they
//! are): while a frame is being drawn the scheduler favours the renderer, and the painter takes
//! what is left. Only the painter's threads change; the UI thread keeps its priority (lowering it
//! too was measured slower). With a GPU there are no such threads and nothing changes.
//! `scripts/window-frame-times.sh` measures both (`docs/window-frame-times.md`).

/// The environment variable: how much to raise the painter threads' nice value, 0 to 19.
pub(crate) const PAINTER_NICE_VARIABLE: &str = "RAYTRACER_PAINTER_NICE";

/// How much the painter threads' nice value is raised unless the environment says otherwise:
/// the scheduler then gives a busy renderer thread about ten times the painter's share.
pub(crate) const DEFAULT_PAINTER_NICE: i32 = 10;

use crate::platform::threads::MAX_NICE;

/// The prefix of the names Mesa gives its software painter's threads.
const PAINTER_THREAD_PREFIX: &str = "llvmpipe-";

/// The raise `value` (of [`PAINTER_NICE_VARIABLE`]) asks for: the default when unset or empty,
/// an error naming the range when it is not a whole number from 0 to 19.
pub(crate) fn painter_nice_asked(value: Option<&std::ffi::OsStr>) -> Result<i32, String> {
    let Some(value) = value.filter(|value| !value.is_empty()) else {
        return Ok(DEFAULT_PAINTER_NICE);
    };
    match value.to_str().map(str::parse::<i32>) {
        Some(Ok(raise)) if (0..=MAX_NICE).contains(&raise) => Ok(raise),
        _ => Err(format!(
            "{PAINTER_NICE_VARIABLE} is {:?}: it must be a whole number from 0 to {MAX_NICE}",
            value.to_string_lossy()
        )),
    }
}

/// [`painter_nice_asked`] by this process's environment.
pub(crate) fn painter_nice_of_environment() -> Result<i32, String> {
    painter_nice_asked(std::env::var_os(PAINTER_NICE_VARIABLE).as_deref())
}

/// Raises the nice value of this process's painter threads by `raise` (at most to 19; 0 leaves
/// them as they are); returns how many painter threads there are, raised (none outside Linux).
pub(crate) fn lower_painter_threads(raise: i32) -> usize {
    crate::platform::threads::lower_threads_named(PAINTER_THREAD_PREFIX, raise)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsStr;

    #[test]
    fn the_painter_nice_variable_takes_0_to_19_and_names_the_range_otherwise() {
        assert_eq!(painter_nice_asked(None), Ok(DEFAULT_PAINTER_NICE));
        assert_eq!(
            painter_nice_asked(Some(OsStr::new(""))),
            Ok(DEFAULT_PAINTER_NICE)
        );
        assert_eq!(painter_nice_asked(Some(OsStr::new("0"))), Ok(0));
        assert_eq!(painter_nice_asked(Some(OsStr::new("19"))), Ok(19));
        for wrong in ["20", "-1", "ten", " 5", "5.0"] {
            let error = painter_nice_asked(Some(OsStr::new(wrong))).unwrap_err();
            assert!(
                error.contains("RAYTRACER_PAINTER_NICE") && error.contains("0 to 19"),
                "{wrong}: {error}"
            );
        }
    }
}
