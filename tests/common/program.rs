//! The program a command-line case runs: the native `raytracer` binary cargo built, or the
//! Windows `raytracer.exe` under Wine (named by `RAYTRACER_WINDOWS_EXE`;
//! `cargo xtask windows test`). The cases in `common/cli_cases.rs` take one and run the same
//! steps against either; what differs between the two (how a path is spelled, whether names
//! differ by case, Wine's own lines on standard error) is answered here.
#![allow(dead_code)] // each test file uses its own share

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// Which build of the command line a case runs.
pub(crate) enum Program {
    /// The binary cargo built for this machine.
    Native,
    /// The Windows `.exe` at this path, run by Wine.
    Windows(PathBuf),
}

impl Program {
    /// The binary cargo built for this machine.
    pub(crate) fn native() -> Self {
        Self::Native
    }

    /// The Windows `.exe` named by `RAYTRACER_WINDOWS_EXE`.
    pub(crate) fn windows() -> Self {
        Self::Windows(windows_exe())
    }

    /// A command that runs the program (through Wine for the `.exe`), with no arguments yet.
    pub(crate) fn command(&self) -> Command {
        match self {
            Self::Native => Command::new(env!("CARGO_BIN_EXE_raytracer")),
            Self::Windows(exe) => wine(exe),
        }
    }

    /// Runs the program in `folder` with `arguments` (paths relative to the folder, as a user
    /// types them), with nothing on standard input.
    pub(crate) fn run(&self, folder: &Path, arguments: &[&str]) -> Output {
        self.command()
            .current_dir(folder)
            .args(arguments)
            .stdin(Stdio::null())
            .output()
            .unwrap()
    }

    /// The program's standard error as text, without Wine's own lines: Wine sometimes reports a
    /// hiccup of its client (one CI run got "wine client error:1ac: sendmsg: Socket operation
    /// on non-socket" after the program's own message), which is not the program's output.
    pub(crate) fn stderr(&self, output: &Output) -> String {
        let text = String::from_utf8_lossy(&output.stderr);
        match self {
            Self::Native => text.into_owned(),
            Self::Windows(_) => text
                .split_inclusive('\n')
                .filter(|line| !line.starts_with("wine client error:"))
                .collect(),
        }
    }

    /// A relative path from its parts, spelled with the platform's separator.
    pub(crate) fn path(&self, parts: &[&str]) -> String {
        parts.join(match self {
            Self::Native => "/",
            Self::Windows(_) => "\\",
        })
    }

    /// Whether the platform takes names that differ only by case for one file.
    pub(crate) fn folds_case(&self) -> bool {
        matches!(self, Self::Windows(_))
    }

    /// Whether this is the Windows `.exe`.
    pub(crate) fn is_windows(&self) -> bool {
        matches!(self, Self::Windows(_))
    }
}

/// The Windows `.exe` under test, named by `RAYTRACER_WINDOWS_EXE`.
pub(crate) fn windows_exe() -> PathBuf {
    let exe = std::env::var_os("RAYTRACER_WINDOWS_EXE")
        .expect("RAYTRACER_WINDOWS_EXE names the Windows raytracer.exe (cargo xtask windows test)");
    PathBuf::from(exe)
}

/// A command running the Windows program `exe` under Wine, quietly.
pub(crate) fn wine(exe: &Path) -> Command {
    let mut command = Command::new("wine");
    command.arg(exe).env("WINEDEBUG", "-all");
    command
}
