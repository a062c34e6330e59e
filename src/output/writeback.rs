//! Files written piece by piece reach the disk while the program makes the next pieces: a thread
//! of its own syncs them whenever asked ([`Writeback::written`]), so the sync that completes a
//! file ([`super::atomic::Staging::finish`]) finds little left to write. The guarantee is the
//! final sync's, as before; only its wait moves earlier, beside work the processor does anyway.
//! `scripts/command-vs-cpp.sh` measures what syncing costs the command.
//!
//! Errors of the early syncs are left to the final sync, which reports its own.

use std::fs::File;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread::{Scope, ScopedJoinHandle};

/// Pieces written between two early syncs.
const PIECES_PER_SYNC: usize = 4;

/// The syncing thread and the way to wake it.
pub(crate) struct Writeback<'scope> {
    wake: Option<Sender<()>>,
    thread: Option<ScopedJoinHandle<'scope, ()>>,
    pieces: usize,
}

impl<'scope> Writeback<'scope> {
    /// Syncs `files` (handles of files being written) on a thread of `scope` whenever
    /// [`Self::written`] says enough is new. Without a thread (none could start) nothing is
    /// synced early.
    pub(crate) fn start<'env>(scope: &'scope Scope<'scope, 'env>, files: Vec<File>) -> Self {
        let (wake, woken) = channel();
        let thread = std::thread::Builder::new()
            .name("writeback".into())
            .spawn_scoped(scope, move || sync_when_woken(&files, &woken))
            .ok();
        Self {
            wake: thread.is_some().then_some(wake),
            thread,
            pieces: 0,
        }
    }

    /// Says another piece of every file was written.
    pub(crate) fn written(&mut self) {
        self.pieces += 1;
        if self.pieces.is_multiple_of(PIECES_PER_SYNC)
            && let Some(wake) = &self.wake
        {
            // The thread may have ended; then there is nothing to wake.
            let _ = wake.send(());
        }
    }

    /// Waits for the sync under way, if any; the thread ends.
    pub(crate) fn stop(mut self) {
        self.end();
    }

    fn end(&mut self) {
        drop(self.wake.take());
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Drop for Writeback<'_> {
    fn drop(&mut self) {
        self.end();
    }
}

/// Syncs `files` each time it is woken (several wakes waiting count as one), until the other
/// side hangs up.
fn sync_when_woken(files: &[File], woken: &Receiver<()>) {
    while woken.recv().is_ok() {
        while woken.try_recv().is_ok() {}
        for file in files {
            let _ = file.sync_data();
        }
    }
}
