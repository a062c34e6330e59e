//! Files written piece by piece reach the disk while the program makes the next pieces: a thread
//! of its own syncs them whenever enough is new ([`Writeback::written`]), so the sync that
//! completes a file ([`super::atomic::Staging::finish`]) finds little left to write. The
//! guarantee is the final sync's, as before; only most of its wait moves earlier, beside work the
//! processor does anyway. `cargo xtask report command-vs-cpp` measures what syncing costs the command.
//!
//! The thread syncs handles that share each file with its writer, and the kernel reports a
//! failed write to the disk once per open file: the first error an early sync meets is kept and
//! returned by [`Writeback::stop`], so that a file that did not reach the disk is never put in
//! place.

use std::fs::File;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread::{Scope, ScopedJoinHandle};

/// Pieces written between two early syncs.
const PIECES_PER_SYNC: usize = 4;

/// An early sync's failure: which file (its index among those given) and why.
pub(crate) type SyncFailure = (usize, std::io::Error);

/// The syncing thread and the way to wake it.
pub(crate) struct Writeback<'scope> {
    wake: Option<Sender<()>>,
    thread: Option<ScopedJoinHandle<'scope, Result<(), SyncFailure>>>,
    pieces: AtomicUsize,
    /// Set once the writing is over: a wake still waiting then syncs nothing (the final sync
    /// does it all).
    stopping: Arc<AtomicBool>,
}

impl<'scope> Writeback<'scope> {
    /// Syncs `files` (handles of files being written) on a thread of `scope` whenever
    /// [`Self::written`] says enough is new. Without a thread (none could start) nothing is
    /// synced early.
    pub(crate) fn start<'env>(scope: &'scope Scope<'scope, 'env>, files: Vec<File>) -> Self {
        let (wake, woken) = channel();
        let stopping = Arc::new(AtomicBool::new(false));
        let told = Arc::clone(&stopping);
        let thread = std::thread::Builder::new()
            .name("writeback".into())
            .spawn_scoped(scope, move || sync_when_woken(&files, &woken, &told))
            .ok();
        Self {
            wake: thread.is_some().then_some(wake),
            thread,
            pieces: AtomicUsize::new(0),
            stopping,
        }
    }

    /// Says another piece of every file was written (from any thread).
    pub(crate) fn written(&self) {
        let pieces = self.pieces.fetch_add(1, Ordering::Relaxed) + 1;
        if pieces.is_multiple_of(PIECES_PER_SYNC)
            && let Some(wake) = &self.wake
        {
            // The thread may have ended (after a failure); then there is nothing to wake.
            let _ = wake.send(());
        }
    }

    /// Ends the thread once the sync under way, if any, is done; returns the first failure of
    /// an early sync.
    pub(crate) fn stop(mut self) -> Result<(), SyncFailure> {
        self.end()
    }

    fn end(&mut self) -> Result<(), SyncFailure> {
        self.stopping.store(true, Ordering::Release);
        drop(self.wake.take());
        match self.thread.take().map(ScopedJoinHandle::join) {
            Some(Ok(synced)) => synced,
            Some(Err(_)) => Err((0, std::io::Error::other("the writeback thread failed"))),
            None => Ok(()),
        }
    }
}

impl Drop for Writeback<'_> {
    fn drop(&mut self) {
        // Dropped on an error path: the files are abandoned anyway.
        let _ = self.end();
    }
}

/// Syncs `files` each time it is woken (several wakes waiting count as one), until the other
/// side hangs up or says it is `stopping`; ends at the first failure.
fn sync_when_woken(
    files: &[File],
    woken: &Receiver<()>,
    stopping: &AtomicBool,
) -> Result<(), SyncFailure> {
    while woken.recv().is_ok() {
        while woken.try_recv().is_ok() {}
        if stopping.load(Ordering::Acquire) {
            break;
        }
        for (index, file) in files.iter().enumerate() {
            file.sync_data().map_err(|error| (index, error))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_early_sync_is_kept_for_the_end() {
        // Every early sync of the second file fails.
        let folder = tempfile::tempdir().unwrap();
        let good = File::create(folder.path().join("good")).unwrap();
        let pipe = crate::platform::files::file_that_cannot_sync(folder.path());
        let failure = std::thread::scope(|scope| {
            let writeback = Writeback::start(scope, vec![good, pipe]);
            for _ in 0..PIECES_PER_SYNC {
                writeback.written();
            }
            // Until the thread has met the failure (it ends then), more pieces come.
            while !writeback
                .thread
                .as_ref()
                .is_none_or(ScopedJoinHandle::is_finished)
            {
                writeback.written();
                std::thread::yield_now();
            }
            writeback.stop()
        });
        let (index, _) = failure.expect_err("the pipe's sync failed");
        assert_eq!(index, 1, "the second file");
    }

    #[test]
    fn files_that_sync_stop_without_an_error() {
        let folder = tempfile::tempdir().unwrap();
        let file = File::create(folder.path().join("a")).unwrap();
        std::thread::scope(|scope| {
            let writeback = Writeback::start(scope, vec![file]);
            for _ in 0..3 * PIECES_PER_SYNC {
                writeback.written();
            }
            assert!(writeback.stop().is_ok());
        });
    }
}
