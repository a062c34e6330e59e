//! Everything that differs by operating system, in one place: no other module names
//! `std::os::unix`, `std::os::windows` or a signal (`tests/layout.rs` checks it). Each file here
//! offers one portable interface with a Unix side and a Windows side:
//! * [`files`]: positional reads and writes, what kind of file a path is, the mode a new file is
//!   created with and a replaced file keeps, and file identity (the same file by two names);
//! * [`process`]: termination signals (Unix) and console control events (Windows), the stop they
//!   ask for, the wake that tells the viewer, and rayon's thread pool;
//! * [`console`]: standard output and error that a closed pipe ends quietly;
//! * [`memory`]: the memory the program may still use, and its peak so far;
//! * [`display`]: whether there is a display server to open a window on;
//! * [`threads`]: work in the background, on a thread where there are threads;
//! * [`worker`]: the viewer's render worker, which runs the newest job on a thread of its own
//!   (in a page, on the page's thread once per frame);
//! * [`watch`]: watching a file for changes (the viewer);
//! * `browser`: in a browser page (`wasm32`), the page's window, address, fetches and downloads.
//!
//! This is the bottom layer: it knows nothing of scenes, pictures or the command line.

#[cfg(target_arch = "wasm32")]
pub mod browser;
pub mod console;
pub mod display;
pub mod files;
pub mod memory;
pub mod process;
pub mod threads;
#[cfg(feature = "gui")]
pub mod watch;
#[cfg(feature = "gui")]
pub mod worker;
