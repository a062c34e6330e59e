//! Progress bars of the command line (indicatif): shown on stderr only when it is a terminal and
//! only once a step has run for [`SHOW_AFTER`], so short runs and scripts see nothing.

use std::sync::OnceLock;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// How long a step runs before its bar appears.
pub(crate) const SHOW_AFTER: Duration = Duration::from_millis(500);

/// Steps of a bar: the share done is shown in thousandths.
const STEPS: u64 = 1000;

/// A lazily shown progress bar for one step (loading, rendering).
pub(crate) struct StepProgress {
    label: &'static str,
    started: Instant,
    bar: OnceLock<ProgressBar>,
}

impl StepProgress {
    /// Starts timing a step named `label`.
    pub(crate) fn start(label: &'static str) -> Self {
        Self {
            label,
            started: Instant::now(),
            bar: OnceLock::new(),
        }
    }

    /// Reports the share done (0 to 1); shows the bar once the step has run for [`SHOW_AFTER`].
    pub(crate) fn report(&self, share: f64) {
        let bar = match self.bar.get() {
            Some(bar) => bar,
            None if self.started.elapsed() >= SHOW_AFTER => self.bar.get_or_init(|| {
                let bar = ProgressBar::with_draw_target(Some(STEPS), ProgressDrawTarget::stderr());
                if let Ok(style) =
                    ProgressStyle::with_template("{msg:>9} [{bar:40}] {percent:>3}% {elapsed}")
                {
                    bar.set_style(style.progress_chars("=> "));
                }
                bar.set_message(self.label);
                bar
            }),
            None => return,
        };
        let share = if share.is_finite() {
            share.clamp(0.0, 1.0)
        } else {
            0.0
        };
        bar.set_position((share * STEPS as f64) as u64);
    }

    #[cfg(test)]
    /// Whether the bar has been created (the step ran longer than [`SHOW_AFTER`]).
    pub(crate) fn was_shown(&self) -> bool {
        self.bar.get().is_some()
    }
}

impl Drop for StepProgress {
    fn drop(&mut self) {
        if let Some(bar) = self.bar.get() {
            bar.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_steps_show_nothing_long_ones_do() {
        let quick = StepProgress::start("quick");
        quick.report(0.5);
        assert!(!quick.was_shown());
        let mut slow = StepProgress::start("slow");
        slow.started -= SHOW_AFTER;
        slow.report(0.5);
        slow.report(f64::NAN); // never panics on odd values
        assert!(slow.was_shown());
    }
}
