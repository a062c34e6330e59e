//! Fuzz target: arbitrary arguments (the input split at zero bytes) through the command line's
//! parser. It never panics, and a render request it accepts, written back to arguments through
//! the flag table, parses to the same request.
#![no_main]

use std::ffi::OsString;
use std::os::unix::ffi::OsStringExt as _;

use libfuzzer_sys::fuzz_target;
use raytracer::cli::{Command, parse_command};

fuzz_target!(|bytes: &[u8]| {
    let arguments: Vec<OsString> = bytes
        .split(|&b| b == 0)
        .map(|word| OsString::from_vec(word.to_vec()))
        .collect();
    let Ok(Command::Render(request)) = parse_command(arguments) else {
        return;
    };
    let again = parse_command(request.to_arguments());
    assert_eq!(again, Ok(Command::Render(request)));
});
