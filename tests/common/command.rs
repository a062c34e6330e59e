//! Helpers shared by the tests that run the real binary (included by path, so that they need no
//! viewer): its standard error as text, and the names in a folder.
#![allow(dead_code)] // each test file uses its own share

use std::path::Path;
use std::process::Output;

/// The run's standard error, as text.
pub(crate) fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The names in `folder`, sorted (hidden ones too).
pub(crate) fn names_in(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}
