//! [`Task`]: the viewer's one mechanism for work off the UI thread that is not rendering —
//! loading a scene, writing an export, waiting for a file dialog. The work runs on a thread of
//! its own; the UI polls for the answer without blocking and is woken when it lands; the work
//! can report its progress. In a browser page, which has no threads, the work runs when the task
//! is started.

use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use web_time::{Duration, Instant};

/// Progress is shared as parts per million of the whole task.
const PROGRESS_SCALE: f64 = 1_000_000.0;

/// Where a task reports the share of its work done.
#[derive(Debug, Clone, Default)]
pub(crate) struct Progress(Arc<AtomicU32>);

impl Progress {
    /// Records that `share` (0 to 1) of the work is done.
    pub(crate) fn report(&self, share: f64) {
        let share = if share.is_nan() { 0.0 } else { share };
        let parts = (share.clamp(0.0, 1.0) * PROGRESS_SCALE) as u32;
        self.0.store(parts, Ordering::Relaxed);
    }

    /// The share done, in [0, 1].
    pub(crate) fn fraction(&self) -> f32 {
        (f64::from(self.0.load(Ordering::Relaxed)) / PROGRESS_SCALE) as f32
    }
}

/// The state of a task.
#[derive(Debug)]
pub(crate) enum Poll<T> {
    /// Still running.
    Running,
    /// Finished with this answer.
    Done(T),
    /// The thread ended without an answer (it panicked).
    Lost,
}

/// Work running on a thread of its own.
#[derive(Debug)]
pub(crate) struct Task<T> {
    answer: Receiver<T>,
    progress: Progress,
    started: Instant,
}

impl<T: Send + 'static> Task<T> {
    /// Runs `work` on a thread named `name`; `ctx` is asked for a repaint when it is done.
    pub(crate) fn spawn(
        name: &str,
        ctx: &egui::Context,
        work: impl FnOnce(&Progress) -> T + Send + 'static,
    ) -> std::io::Result<Self> {
        let (sender, answer) = channel();
        let progress = Progress::default();
        let shared = progress.clone();
        let ctx = ctx.clone();
        // In a browser page the work runs now, and its answer waits in the channel.
        crate::platform::threads::run_in_background(name, move || {
            // The viewer may have closed or dropped the task; then nobody listens.
            let _ = sender.send(work(&shared));
            ctx.request_repaint();
        })?;
        Ok(Self {
            answer,
            progress,
            started: Instant::now(),
        })
    }

    /// Checks for the answer without blocking.
    pub(crate) fn poll(&self) -> Poll<T> {
        match self.answer.try_recv() {
            Ok(answer) => Poll::Done(answer),
            Err(TryRecvError::Empty) => Poll::Running,
            Err(TryRecvError::Disconnected) => Poll::Lost,
        }
    }

    /// The share of the work done, as the work reported it.
    pub(crate) fn fraction(&self) -> f32 {
        self.progress.fraction()
    }

    /// How long the task has run.
    pub(crate) fn elapsed(&self) -> Duration {
        self.started.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_task_reports_progress_and_its_answer() {
        let ctx = egui::Context::default();
        let (go, wait) = channel::<()>();
        let task = Task::spawn("test", &ctx, move |progress| {
            progress.report(0.25);
            let _ = wait.recv();
            42
        })
        .unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        while task.fraction() < 0.25 && Instant::now() < deadline {
            std::thread::yield_now();
        }
        assert_eq!(task.fraction(), 0.25);
        assert!(matches!(task.poll(), Poll::Running));
        go.send(()).unwrap();
        loop {
            match task.poll() {
                Poll::Done(answer) => break assert_eq!(answer, 42),
                Poll::Running if Instant::now() < deadline => std::thread::yield_now(),
                other => panic!("{other:?}"),
            }
        }
    }

    #[test]
    fn a_task_whose_thread_panics_is_lost_not_hung() {
        let ctx = egui::Context::default();
        let task: Task<u32> = Task::spawn("test", &ctx, |_| panic!("deliberate")).unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        loop {
            match task.poll() {
                Poll::Lost => break,
                Poll::Running if Instant::now() < deadline => std::thread::yield_now(),
                other => panic!("{other:?}"),
            }
        }
    }
}
