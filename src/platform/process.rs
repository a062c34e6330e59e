//! What the binary needs of the process it runs in, so that the edges never panic and nothing is
//! left behind:
//! * [`start_thread_pool`]: rayon's pool, as large as the process may start, and the calling
//!   thread alone where no thread can be started (a process limit);
//! * [`handle_termination_signals`]: when the user or the system asks the program to stop, the
//!   caller's clean-up runs (the command line removes the temporary files being written) and the
//!   program ends — at once on the command line, after the viewer has saved its settings in the
//!   window. On Unix that is SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM,
//!   SIGVTALRM, SIGXCPU, SIGPROF, or on Linux SIGIO and SIGPWR (every named signal whose default
//!   action ends the program, but SIGKILL, SIGPIPE, which is ignored, and a crash's),
//!   and the program ends with 128 + the signal's number, as shells report it; SIGXFSZ (a file-size limit) is caught so that the
//!   write fails with an error instead of killing the program. On Windows it is the console's
//!   Ctrl-C and Ctrl-Break (through the `ctrlc` crate), both reported as an interrupt: status
//!   130, as Ctrl-C gives on Unix. Closing the console window ends the program at once (Windows
//!   gives a handler no time to clean up once it has answered), as does `taskkill /F`.

use std::sync::atomic::{AtomicI32, Ordering};
use std::sync::{Arc, Mutex, PoisonError};

/// Starts rayon's global pool with as many threads as the machine has cores and the process may
/// start; where no thread can be started (a process limit), the calling thread does all the work.
/// Returns why even that failed (not expected: it starts no thread).
pub fn start_thread_pool() -> Result<(), rayon::ThreadPoolBuildError> {
    let wanted = std::thread::available_parallelism().map_or(1, usize::from);
    let startable = count_startable_threads(wanted);
    // Named, so that a profiler or `top -H` tells the renderer's threads from the painter's.
    let builder = rayon::ThreadPoolBuilder::new().thread_name(|index| format!("rayon-{index}"));
    let builder = match startable {
        0 => builder.num_threads(1).use_current_thread(),
        n => builder.num_threads(n),
    };
    builder.build_global()
}

/// How many of `wanted` threads can be started at once (each is started, then ended).
fn count_startable_threads(wanted: usize) -> usize {
    let (release, wait) = std::sync::mpsc::channel::<()>();
    let wait = Arc::new(Mutex::new(wait));
    let started: Vec<_> = (0..wanted)
        .map_while(|_| {
            let wait = Arc::clone(&wait);
            std::thread::Builder::new()
                .spawn(move || {
                    let _ = wait.lock().unwrap_or_else(PoisonError::into_inner).recv();
                })
                .ok()
        })
        .collect();
    let count = started.len();
    drop(release);
    for thread in started {
        let _ = thread.join();
    }
    count
}

/// What the program does when it is asked to stop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OnSignal {
    /// Clean up and exit at once (the command line).
    Exit,
    /// Ask the viewer to close (it saves its settings) and exit once it has; a second request
    /// cleans up and exits at once.
    CloseViewer,
}

/// The signal that asked the program to stop, if one did (0: none).
static STOP_SIGNAL: AtomicI32 = AtomicI32::new(0);

/// Wakes the viewer so that it sees [`stop_requested`].
type Wake = Box<dyn Fn() + Send>;
static WAKE: Mutex<Option<Wake>> = Mutex::new(None);

/// The signal number of an interrupt (Ctrl-C), the one every Windows stop is reported as.
#[cfg(windows)]
const SIGINT: i32 = 2;

/// The signal that asked the program to stop, if any (on Windows, an interrupt).
pub fn stop_requested() -> Option<i32> {
    match STOP_SIGNAL.load(Ordering::Acquire) {
        0 => None,
        signal => Some(signal),
    }
}

/// Where a signal asked the program to stop while it was ending on an error (a write that failed
/// because the signal's clean-up removed the unfinished files under it), the program ends as
/// stopped: the clean-up, on the signals' thread, exits with the signal's status once it is
/// done; this waits for it, and exits so itself after [`STOPPED_WAIT`] should it not.
pub fn end_as_stopped_if_asked() {
    if let Some(signal) = stop_requested() {
        std::thread::sleep(STOPPED_WAIT);
        std::process::exit(i32::from(exit_status_of(signal)));
    }
}

/// How long [`end_as_stopped_if_asked`] waits for the signal's clean-up to end the program.
const STOPPED_WAIT: std::time::Duration = std::time::Duration::from_secs(10);

/// Sets what wakes the viewer's event loop when a signal asks it to stop.
pub fn set_wake(wake: impl Fn() + Send + 'static) {
    *WAKE.lock().unwrap_or_else(PoisonError::into_inner) = Some(Box::new(wake));
}

/// The exit status for a stop by `signal`: 128 + its number, as shells report it.
pub fn exit_status_of(signal: i32) -> u8 {
    u8::try_from(128 + signal).unwrap_or(u8::MAX)
}

/// A stop asked for by `signal`: the viewer is woken the first time; otherwise `clean_up` runs
/// and the program exits. (A browser page has no signals.)
#[cfg_attr(target_arch = "wasm32", allow(dead_code))]
fn stop(signal: i32, on_signal: OnSignal, clean_up: fn()) {
    let first = STOP_SIGNAL.swap(signal, Ordering::AcqRel) == 0;
    if on_signal == OnSignal::CloseViewer && first {
        if let Some(wake) = WAKE.lock().unwrap_or_else(PoisonError::into_inner).as_ref() {
            wake();
        }
        return;
    }
    clean_up();
    std::process::exit(i32::from(exit_status_of(signal)));
}

/// Installs the handling of stop requests described in the module docs; `clean_up` runs before
/// the program exits on one. Where no thread can be started for it, the requests keep their
/// default action (the program ends at once).
#[cfg(unix)]
pub fn handle_termination_signals(on_signal: OnSignal, clean_up: fn()) {
    use signal_hook::consts::{
        SIGALRM, SIGHUP, SIGINT, SIGPROF, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGVTALRM, SIGXCPU,
        SIGXFSZ,
    };
    // A file-size limit makes writes fail (EFBIG) instead of killing the program.
    let _ =
        signal_hook::flag::register(SIGXFSZ, Arc::new(std::sync::atomic::AtomicBool::new(false)));
    // The handlers are registered on the thread that serves them, so that they never exist
    // without it; the program goes on once they are (a signal that came before would end it
    // the default way, or not at all where the parent ignores it).
    let (registered, ready) = std::sync::mpsc::channel();
    let spawned = std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            // Every signal whose default action ends the program and that a user or a system
            // sends to stop one (not SIGKILL, which cannot be caught, nor a crash's).
            // SIGXCPU is a CPU-time limit (`ulimit -t`) reached; SIGPROF a profiling timer;
            // on Linux, where their default ends a program, SIGIO (SIGPOLL: a file descriptor
            // ready) and SIGPWR (a power failure). SIGPIPE
            // is ignored (Rust's runtime does it): a write to a closed pipe fails with an error
            // the program reports, and `kill -PIPE` does nothing.
            #[cfg_attr(
                not(any(target_os = "linux", target_os = "android")),
                expect(unused_mut, reason = "SIGIO and SIGPWR end a program on Linux only")
            )]
            let mut stopping = vec![
                SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGXCPU,
                SIGPROF,
            ];
            #[cfg(any(target_os = "linux", target_os = "android"))]
            stopping.extend([
                signal_hook::consts::SIGIO,
                rustix::process::Signal::POWER.as_raw(),
            ]);
            let Ok(mut signals) = signal_hook::iterator::Signals::new(stopping) else {
                return;
            };
            let _ = registered.send(());
            for signal in signals.forever() {
                stop(signal, on_signal, clean_up);
            }
        });
    if spawned.is_ok() {
        // An error: the thread ended without registering them.
        let _ = ready.recv();
    }
}

/// Installs the handling of stop requests described in the module docs; `clean_up` runs before
/// the program exits on one. Where the handler cannot be set, Ctrl-C and Ctrl-Break keep their
/// default action (the program ends at once).
#[cfg(windows)]
pub fn handle_termination_signals(on_signal: OnSignal, clean_up: fn()) {
    // ctrlc serves the events on a thread of its own.
    let _ = ctrlc::try_set_handler(move || stop(SIGINT, on_signal, clean_up));
}
