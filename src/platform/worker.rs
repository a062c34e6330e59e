//! A background render worker for interactive use: the caller submits jobs and never blocks; one
//! thread runs the newest job (the renderer itself fans out over rayon's pool); a job submitted
//! while another waits replaces it, and a result older than one already delivered is dropped. A
//! callback (e.g. "request a repaint") runs when a result lands.
//!
//! The worker is generic over the job `J` and its output `T`, so a viewer can have the worker
//! also prepare what it uploads (e.g. texture pixels) off the UI thread. It is here, in the
//! platform layer, because all that differs between the desktop and a page is how it runs: a
//! browser page has no threads, so there it runs the newest job on the page's thread, once per
//! frame.

use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread::JoinHandle;
use web_time::{Duration, Instant};

/// A finished job.
#[derive(Debug, Clone)]
pub(crate) struct RenderResult<J, T> {
    /// Number returned by [`RenderWorker::submit`] for this job; later jobs have larger numbers.
    #[cfg_attr(target_arch = "wasm32", allow(dead_code))]
    pub(crate) generation: u64,
    /// The job that was run.
    pub(crate) job: J,
    /// What the job function returned.
    pub(crate) output: T,
    /// Time spent running the job.
    pub(crate) render_time: Duration,
}

struct Queued<J> {
    generation: u64,
    job: J,
}

struct State<J, T> {
    pending: Option<Queued<J>>,
    finished: Option<RenderResult<J, T>>,
    busy: bool,
    shutdown: bool,
    next_generation: u64,
    #[cfg_attr(target_arch = "wasm32", allow(dead_code))]
    delivered_generation: Option<u64>,
}

struct Shared<J, T> {
    state: Mutex<State<J, T>>,
    wake: Condvar,
}

impl<J, T> Shared<J, T> {
    fn lock(&self) -> MutexGuard<'_, State<J, T>> {
        // A panic while holding the lock cannot leave State inconsistent (plain fields).
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// The worker; dropping it stops its thread after the job in flight.
pub(crate) struct RenderWorker<J, T> {
    shared: Arc<Shared<J, T>>,
    thread: Option<JoinHandle<()>>,
    /// In a browser page, where no thread can be started: the job function, run by
    /// [`RenderWorker::take_finished`] on the caller's thread.
    #[cfg(target_arch = "wasm32")]
    run_job: Box<dyn Fn(&J) -> T>,
    /// In a browser page: wakes the caller to come back for a submitted job.
    #[cfg(target_arch = "wasm32")]
    on_submitted: Box<dyn Fn()>,
}

impl<J, T> std::fmt::Debug for RenderWorker<J, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RenderWorker").finish_non_exhaustive()
    }
}

impl<J: Clone + Send + 'static, T: Send + 'static> RenderWorker<J, T> {
    /// Starts the worker thread: it runs `run_job` on each job it takes, and `on_finished` after
    /// each result is stored.
    #[cfg_attr(target_arch = "wasm32", allow(clippy::unnecessary_wraps))]
    pub(crate) fn new(
        run_job: impl Fn(&J) -> T + Send + 'static,
        on_finished: impl Fn() + Send + 'static,
    ) -> std::io::Result<Self> {
        let shared = Arc::new(Shared {
            state: Mutex::new(State {
                pending: None,
                finished: None,
                busy: false,
                shutdown: false,
                next_generation: 0,
                delivered_generation: None,
            }),
            wake: Condvar::new(),
        });
        #[cfg(not(target_arch = "wasm32"))]
        {
            let worker_shared = Arc::clone(&shared);
            let thread = std::thread::Builder::new()
                .name("render-worker".into())
                .spawn(move || worker_loop(&worker_shared, &run_job, &on_finished))?;
            Ok(Self {
                shared,
                thread: Some(thread),
            })
        }
        #[cfg(target_arch = "wasm32")]
        {
            Ok(Self {
                shared,
                thread: None,
                run_job: Box::new(run_job),
                on_submitted: Box::new(on_finished),
            })
        }
    }

    /// Queues `job`, replacing any job not yet started. Returns the job's generation.
    pub(crate) fn submit(&self, job: J) -> u64 {
        let mut state = self.shared.lock();
        let generation = state.next_generation;
        state.next_generation += 1;
        state.pending = Some(Queued { generation, job });
        drop(state);
        self.shared.wake.notify_all();
        #[cfg(target_arch = "wasm32")]
        (self.on_submitted)();
        generation
    }

    /// The newest finished frame not yet taken, if any. In a browser page, the job waiting is
    /// run here, on the caller's thread: one job per call, so the page draws between jobs.
    pub(crate) fn take_finished(&self) -> Option<RenderResult<J, T>> {
        #[cfg(target_arch = "wasm32")]
        {
            let queued = self.shared.lock().pending.take();
            if let Some(queued) = queued {
                let started = Instant::now();
                let output = (self.run_job)(&queued.job);
                return Some(RenderResult {
                    generation: queued.generation,
                    job: queued.job,
                    output,
                    render_time: started.elapsed(),
                });
            }
        }
        self.shared.lock().finished.take()
    }

    /// True when no job is waiting or running.
    pub(crate) fn is_idle(&self) -> bool {
        let state = self.shared.lock();
        state.pending.is_none() && !state.busy
    }

    /// Blocks until the worker is idle or `timeout` passes; true if idle (for tests and exports).
    pub(crate) fn wait_idle(&self, timeout: Duration) -> bool {
        // In a browser page nothing runs the job meanwhile: waiting would never end.
        #[cfg(target_arch = "wasm32")]
        if cfg!(target_arch = "wasm32") {
            let _ = timeout;
            return self.is_idle();
        }
        let deadline = Instant::now() + timeout;
        let mut state = self.shared.lock();
        while state.pending.is_some() || state.busy {
            let now = Instant::now();
            if now >= deadline {
                return false;
            }
            state = self
                .shared
                .wake
                .wait_timeout(state, deadline - now)
                .unwrap_or_else(PoisonError::into_inner)
                .0;
        }
        true
    }
}

impl<J, T> Drop for RenderWorker<J, T> {
    fn drop(&mut self) {
        self.shared.lock().shutdown = true;
        self.shared.wake.notify_all();
        if let Some(thread) = self.thread.take() {
            // A panicked worker has nothing left to clean up.
            let _ = thread.join();
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn worker_loop<J: Clone, T>(
    shared: &Shared<J, T>,
    run_job: &dyn Fn(&J) -> T,
    on_finished: &dyn Fn(),
) {
    loop {
        let queued = {
            let mut state = shared.lock();
            loop {
                if state.shutdown {
                    return;
                }
                if let Some(queued) = state.pending.take() {
                    state.busy = true;
                    break queued;
                }
                state = shared
                    .wake
                    .wait(state)
                    .unwrap_or_else(PoisonError::into_inner);
            }
        };
        let started = Instant::now();
        let output = run_job(&queued.job);
        let result = RenderResult {
            generation: queued.generation,
            job: queued.job,
            output,
            render_time: started.elapsed(),
        };
        {
            let mut state = shared.lock();
            // Drop a result older than one already handed over.
            if state
                .delivered_generation
                .is_none_or(|d| result.generation > d)
            {
                state.delivered_generation = Some(result.generation);
                state.finished = Some(result);
            }
        }
        on_finished();
        // Idle only once the callback has run, so a waiter sees its effect.
        shared.lock().busy = false;
        shared.wake.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::depth_map::DepthRange;
    use crate::render::{Frame, View, ViewError, render};
    use crate::scene::{Scene, parse_scene};
    use std::sync::atomic::{AtomicUsize, Ordering};

    type Job = (Arc<Scene>, View);

    fn frame_worker(
        on_finished: impl Fn() + Send + 'static,
    ) -> RenderWorker<Job, Result<Frame, ViewError>> {
        RenderWorker::new(|(scene, view): &Job| render(scene, view), on_finished).unwrap()
    }

    fn scene() -> Arc<Scene> {
        Arc::new(
            parse_scene(
                "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }
                 Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }",
            )
            .unwrap(),
        )
    }

    #[test]
    fn renders_the_newest_job_and_calls_back() {
        let calls = Arc::new(AtomicUsize::new(0));
        let counter = Arc::clone(&calls);
        let worker = frame_worker(move || {
            counter.fetch_add(1, Ordering::SeqCst);
        });
        let scene = scene();
        let view = View::of_camera(&scene.camera, 32, 32, DepthRange::new(9.0, 10.0));
        let mut last = 0;
        for width in 1..=20 {
            last = worker.submit((
                Arc::clone(&scene),
                View {
                    width_px: width,
                    ..view
                },
            ));
        }
        assert!(worker.wait_idle(Duration::from_secs(10)));
        let result = worker.take_finished().unwrap();
        assert_eq!(
            result.generation, last,
            "the newest job is the one delivered"
        );
        assert_eq!(result.output.unwrap().width_px, 20);
        assert!(calls.load(Ordering::SeqCst) >= 1);
        assert!(worker.take_finished().is_none(), "taken once");
    }

    #[test]
    fn invalid_view_is_reported_not_a_panic() {
        let worker = frame_worker(|| {});
        let scene = scene();
        let view = View::of_camera(&scene.camera, 0, 32, DepthRange::new(9.0, 10.0));
        worker.submit((scene, view));
        assert!(worker.wait_idle(Duration::from_secs(10)));
        assert!(worker.take_finished().unwrap().output.is_err());
    }
}
