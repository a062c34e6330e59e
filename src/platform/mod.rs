//! Everything that differs by operating system, in one place: no other module names
//! `std::os::unix`, `std::os::windows` or a signal (`tests/layout.rs` checks it). Each file here
//! offers one portable interface with a Unix side and a Windows side:
//! * [`files`]: positional reads and writes, what kind of file a path is, the mode a new file is
//!   created with and a replaced file keeps, and file identity (the same file by two names);
//! * [`process`]: termination signals (Unix) and console control events (Windows), the stop they
//!   ask for, the wake that tells the viewer, and rayon's thread pool;
//! * [`console`]: standard output and error that a closed pipe ends quietly;
//! * [`memory`]: the memory the program may still use, and its peak so far;
//! * [`display`]: whether there is a display server to open a window on.
//!
//! This is the bottom layer: it knows nothing of scenes, pictures or the command line.

pub mod console;
pub mod display;
pub mod files;
pub mod memory;
pub mod process;
