//! Where a frame's time goes: the named phases of a render (projection, the plan, clearing, a
//! dense frame's cull, "sort and bin" (a pass's depth sort, its discs placed and binned) and
//! coarse depth, binning, drawing, shading, and the viewer's histogram and textures), timed when
//! asked for by [`measure`]. `examples/frame_phases` prints them at each thread count, to find the
//! parts that do not scale with cores (`cargo xtask report scaling`). Off unless measuring: a phase then
//! costs one relaxed atomic load.
//!
//! The recording is process-wide: phases that other threads run while [`measure`] runs are
//! recorded too. Measure one frame at a time.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

// The browser's clock in a page, where `std::time::Instant` panics.
use web_time::Instant;

/// Whether phases are being recorded.
static RECORDING: AtomicBool = AtomicBool::new(false);
/// The phases recorded since [`measure`] began: name and milliseconds, in the order they ended.
static RECORDED: Mutex<Vec<(&'static str, f64)>> = Mutex::new(Vec::new());

/// A phase's name and its wall time in milliseconds.
pub type PhaseTime = (&'static str, f64);

/// Runs `work`, recording the wall time of every phase run inside it. Returns `work`'s result and
/// the phases in the order they ended (a phase run several times, such as a pass's drawing, is
/// listed each time).
pub fn measure<R>(work: impl FnOnce() -> R) -> (R, Vec<PhaseTime>) {
    /// Stops the recording when dropped, also when `work` panics.
    struct Stop;
    impl Drop for Stop {
        fn drop(&mut self) {
            RECORDING.store(false, Ordering::Relaxed);
        }
    }
    lock().clear();
    RECORDING.store(true, Ordering::Relaxed);
    let stop = Stop;
    let result = work();
    drop(stop);
    (result, std::mem::take(&mut *lock()))
}

/// Runs `phase`, recording its wall time under `name` while [`measure`] runs.
#[inline]
pub(crate) fn time<R>(name: &'static str, phase: impl FnOnce() -> R) -> R {
    if !RECORDING.load(Ordering::Relaxed) {
        return phase();
    }
    let started = Instant::now();
    let result = phase();
    let ms = started.elapsed().as_secs_f64() * 1e3;
    lock().push((name, ms));
    result
}

/// The recorded phases, whatever a panicking holder left (a list of timings cannot be broken).
fn lock() -> std::sync::MutexGuard<'static, Vec<PhaseTime>> {
    RECORDED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}
