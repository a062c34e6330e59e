//! `cargo xtask`: the project's chores behind one command (the alias is in `.cargo/config.toml`).
//!
//! A chore is a Bash file in `xtask/chores/`; its name is the file's, and its help is the comment
//! at the file's top, so a chore's usage is written once, beside its steps. The tool lists the
//! chores (`cargo xtask --help`), prints one's help (`cargo xtask CHORE --help`), refuses a name
//! it does not know, and otherwise runs the chore from the repository's root, from whatever folder
//! it was called in, exiting with the chore's status.
//!
//! Why Bash under a Rust front: the chores drive other programs (apt, rustup, Xvfb, Wine,
//! Chromium, npm, ImageMagick) and pipe their output, which a shell says in a line where Rust
//! takes ten; the front gives them the entry point a Rust contributor looks for, one list, one
//! `--help` each, and the same behaviour from any folder. It has no dependencies, so it builds in
//! seconds before the first chore.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

/// One chore: `xtask/chores/NAME.sh`.
struct Chore {
    name: String,
    file: PathBuf,
}

impl Chore {
    /// The comment at the file's top (after the `#!` line), without its `# ` marks.
    fn help(&self) -> Result<String, String> {
        let text = std::fs::read_to_string(&self.file)
            .map_err(|error| format!("cannot read {}: {error}", self.file.display()))?;
        let help: Vec<&str> = text
            .lines()
            .skip_while(|line| line.starts_with("#!"))
            .take_while(|line| line.starts_with('#'))
            .map(|line| line.trim_start_matches('#').strip_prefix(' ').unwrap_or(""))
            .collect();
        Ok(help.join("\n"))
    }

    /// The help's first line, for the list.
    fn summary(&self) -> String {
        self.help()
            .ok()
            .and_then(|help| help.lines().next().map(str::to_owned))
            .unwrap_or_default()
    }
}

/// The repository's root: the folder above this crate's.
fn root() -> PathBuf {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    here.parent().unwrap_or(here).to_path_buf()
}

/// Every chore, by name.
fn chores(root: &Path) -> Result<Vec<Chore>, String> {
    let folder = root.join("xtask/chores");
    let entries = std::fs::read_dir(&folder)
        .map_err(|error| format!("cannot read {}: {error}", folder.display()))?;
    let mut chores: Vec<Chore> = entries
        .flatten()
        .map(|entry| entry.path())
        .filter(|file| file.extension().is_some_and(|extension| extension == "sh"))
        .filter_map(|file| {
            let name = file.file_stem()?.to_str()?.to_owned();
            Some(Chore { name, file })
        })
        .collect();
    chores.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(chores)
}

fn list(chores: &[Chore]) -> String {
    let width = chores
        .iter()
        .map(|chore| chore.name.len())
        .max()
        .unwrap_or(0);
    let mut text = String::from(
        "usage: cargo xtask CHORE [ARG…]\n       cargo xtask CHORE --help    what it does, its arguments\n\nchores:\n",
    );
    for chore in chores {
        text += &format!("  {:width$}  {}\n", chore.name, chore.summary());
    }
    text
}

fn is_help(word: &str) -> bool {
    matches!(word, "--help" | "-h" | "help")
}

fn main() -> ExitCode {
    let root = root();
    let chores = match chores(&root) {
        Ok(chores) => chores,
        Err(message) => {
            eprintln!("cargo xtask: {message}");
            return ExitCode::FAILURE;
        }
    };
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let Some(name) = arguments.first() else {
        eprint!("{}", list(&chores));
        return ExitCode::from(2);
    };
    if is_help(name) {
        print!("{}", list(&chores));
        return ExitCode::SUCCESS;
    }
    let Some(chore) = chores.iter().find(|chore| &chore.name == name) else {
        let names: Vec<&str> = chores.iter().map(|chore| chore.name.as_str()).collect();
        eprintln!(
            "cargo xtask: no chore named '{name}'; the chores: {} (cargo xtask --help)",
            names.join(", ")
        );
        return ExitCode::from(2);
    };
    if arguments.get(1).is_some_and(|word| is_help(word)) {
        return match chore.help() {
            Ok(help) => {
                println!("{help}");
                ExitCode::SUCCESS
            }
            Err(message) => {
                eprintln!("cargo xtask: {message}");
                ExitCode::FAILURE
            }
        };
    }
    let status = Command::new(bash())
        .arg(&chore.file)
        .args(&arguments[1..])
        .current_dir(&root)
        .status();
    match status {
        Ok(status) => exit_code(status),
        Err(error) => {
            eprintln!("cargo xtask: cannot run bash for '{name}': {error}");
            ExitCode::FAILURE
        }
    }
}

/// The shell that runs the chores. On Windows, the first `bash.exe` on the PATH that is not
/// the one in the system folder (WSL's launcher, which Windows would otherwise pick before the
/// PATH): Git for Windows' bash, as the release workflow's `shell: bash` uses.
fn bash() -> PathBuf {
    if cfg!(windows) {
        let path = std::env::var_os("PATH").unwrap_or_default();
        for folder in std::env::split_paths(&path) {
            let lower = folder.to_string_lossy().to_lowercase();
            let candidate = folder.join("bash.exe");
            if !lower.contains("system32") && !lower.contains("windowsapps") && candidate.is_file()
            {
                return candidate;
            }
        }
    }
    PathBuf::from("bash")
}

/// The chore's status; a chore ended by a signal exits 128 + the signal, as a shell reports it.
fn exit_code(status: std::process::ExitStatus) -> ExitCode {
    if let Some(code) = status.code() {
        return ExitCode::from(u8::try_from(code).unwrap_or(1));
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            return ExitCode::from(u8::try_from(128 + signal).unwrap_or(1));
        }
    }
    ExitCode::FAILURE
}
