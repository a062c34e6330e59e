//! Work in the background: on a thread of its own where the platform has threads, and at once in a
//! browser page, which starts none (the answer then waits for whoever asked, as a thread's would).

/// Runs `work` on a new thread named `name`; in a browser page, runs it now, before returning.
pub fn run_in_background(name: &str, work: impl FnOnce() + Send + 'static) -> std::io::Result<()> {
    #[cfg(target_arch = "wasm32")]
    {
        let _ = name;
        work();
        Ok(())
    }
    #[cfg(not(target_arch = "wasm32"))]
    std::thread::Builder::new()
        .name(name.to_owned())
        .spawn(work)
        .map(drop)
}
