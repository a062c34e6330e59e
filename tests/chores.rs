//! The chores' one tool, `cargo xtask`, as a contributor meets it: the real tool built and run
//! from a folder of the repository.
//! * `cargo xtask --help` lists every chore of `xtask/chores/` with its one-line summary;
//! * `cargo xtask CHORE --help` prints the chore's usage and runs nothing;
//! * a name that is no chore is refused with exit status 2 and the list of names;
//! * a chore runs at the repository's root from any folder, and its status is the tool's;
//! * every `cargo xtask CHORE WORD` that the README, docs/, CI, the workflows, the source and the
//!   chores themselves write names a chore, and a word the chore's help knows; every chore is
//!   named where a contributor reads (the README, docs/ or CI).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The tool, built once into a folder of its own (the suite's own build holds `target/`).
fn tool() -> &'static Path {
    static TOOL: OnceLock<PathBuf> = OnceLock::new();
    TOOL.get_or_init(|| {
        let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("xtask");
        let built = Command::new(option_env!("CARGO").unwrap_or("cargo"))
            .args(["build", "--quiet", "--package", "xtask", "--target-dir"])
            .arg(&target)
            .current_dir(root())
            .status()
            .expect("cargo runs");
        assert!(built.success(), "the xtask tool builds");
        target
            .join("debug")
            .join(format!("xtask{}", std::env::consts::EXE_SUFFIX))
    })
}

fn xtask(folder: &Path, arguments: &[&str]) -> Output {
    Command::new(tool())
        .args(arguments)
        .current_dir(folder)
        .output()
        .expect("the xtask tool runs")
}

/// Every file under `folder`, build and package folders left out.
fn files_under(folder: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut folders = vec![folder.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).into_iter().flatten().flatten() {
            let path = entry.path();
            let name = entry.file_name();
            if path.is_dir() {
                if !matches!(name.to_str(), Some("node_modules" | "target" | "corpus")) {
                    folders.push(path);
                }
            } else {
                found.push(path);
            }
        }
    }
    found
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The chores, read from the folder as a contributor would see it: (name, its file's text).
fn chore_files() -> Vec<(String, String)> {
    let mut chores: Vec<(String, String)> = std::fs::read_dir(root().join("xtask/chores"))
        .unwrap()
        .flatten()
        .filter_map(|entry| {
            let name = entry.file_name().to_string_lossy().into_owned();
            let name = name.strip_suffix(".sh")?.to_owned();
            Some((name, std::fs::read_to_string(entry.path()).unwrap()))
        })
        .collect();
    chores.sort();
    assert!(chores.len() >= 8, "only {} chores found", chores.len());
    chores
}

#[test]
fn the_list_names_every_chore_with_its_summary() {
    let listed = xtask(root(), &["--help"]);
    assert_eq!(listed.status.code(), Some(0));
    let stdout = text(&listed.stdout);
    for (name, file) in chore_files() {
        let summary = file.lines().nth(1).unwrap().trim_start_matches("# ");
        assert!(
            summary.ends_with('.'),
            "xtask/chores/{name}.sh: its second line is not a one-sentence summary: {summary}"
        );
        let row = stdout
            .lines()
            .find(|line| line.split_whitespace().next() == Some(name.as_str()))
            .unwrap_or_else(|| panic!("`{name}` is not listed:\n{stdout}"));
        assert!(
            row.ends_with(summary),
            "`{name}`'s row lacks its summary: {row}"
        );
    }
    let bare = xtask(root(), &[]);
    assert_eq!(
        bare.status.code(),
        Some(2),
        "no chore named is a usage error"
    );
    assert!(text(&bare.stderr).contains("usage: cargo xtask CHORE"));
}

#[test]
fn every_chore_says_how_to_call_it_and_help_runs_nothing() {
    for (name, _) in chore_files() {
        for help in ["--help", "-h"] {
            let output = xtask(root(), &[&name, help]);
            let stdout = text(&output.stdout);
            assert_eq!(output.status.code(), Some(0), "`{name} {help}`");
            assert!(
                stdout.contains(&format!("cargo xtask {name}")),
                "`cargo xtask {name} {help}` gives no usage line:\n{stdout}"
            );
            // The report chore prints `== NAME` as it runs each report; help must run none.
            assert!(
                !stdout.contains("== ") && output.stderr.is_empty(),
                "`cargo xtask {name} {help}` ran something:\n{stdout}{}",
                text(&output.stderr)
            );
        }
    }
}

#[test]
fn a_name_that_is_no_chore_is_refused_with_the_list() {
    let output = xtask(root(), &["tests"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(output.stdout.is_empty());
    let stderr = text(&output.stderr);
    assert!(stderr.contains("no chore named 'tests'"), "{stderr}");
    for (name, _) in chore_files() {
        assert!(
            stderr.contains(&name),
            "the refusal does not list `{name}`: {stderr}"
        );
    }
}

#[test]
fn a_chore_runs_at_the_root_from_any_folder_and_its_status_is_the_tools() {
    // From a folder below the root: the chore finds its own files (it would fail to read
    // xtask/reports/ otherwise), says why it refuses and exits 2, as the tool then does.
    let folder = root().join("tests/common");
    let report = xtask(&folder, &["report", "no-such-report"]);
    assert_eq!(report.status.code(), Some(2));
    assert!(
        text(&report.stderr).contains("cargo xtask report: unknown report 'no-such-report'"),
        "{}",
        text(&report.stderr)
    );
    let fuzz = xtask(&folder, &["fuzz", "a-minute"]);
    assert_eq!(fuzz.status.code(), Some(2));
    assert!(text(&fuzz.stderr).contains("usage: cargo xtask fuzz"));
    // A status other than 2 comes through unchanged: the sync of the README's tables ends 0 when
    // it runs from a subfolder and finds the reports at the root (and, the tables being in sync,
    // changes nothing: tests/docs.rs checks that).
    let sync = xtask(&folder, &["report", "sync"]);
    assert_eq!(sync.status.code(), Some(0), "{}", text(&sync.stderr));
    assert!(text(&sync.stdout).contains("== sync"));
}

/// Every `cargo xtask …` written in the files a contributor reads or runs: (file, the words after
/// `cargo xtask`).
fn written_calls() -> Vec<(String, Vec<String>)> {
    let mut files = vec![root().join("README.md"), root().join(".ci/run")];
    for folder in ["docs", "xtask", "src", "tests", "examples", ".github"] {
        files.extend(
            files_under(&root().join(folder))
                .into_iter()
                .filter(|file| {
                    let name = file.to_string_lossy();
                    [".md", ".rs", ".sh", ".yml", ".mjs", ".txt"]
                        .iter()
                        .any(|end| name.ends_with(end))
                }),
        );
    }
    let mut calls = Vec::new();
    for file in files {
        let Ok(content) = std::fs::read_to_string(&file) else {
            continue;
        };
        let relative = file.strip_prefix(root()).unwrap().display().to_string();
        if relative == "tests/chores.rs" {
            continue; // this file's own examples
        }
        for (at, _) in content.match_indices("cargo xtask ") {
            let words: Vec<String> = content[at + "cargo xtask ".len()..]
                .split(['`', '\\', '\n', ')', ';', ',', '"', '|', '\''])
                .next()
                .unwrap()
                .split_whitespace()
                .take(2)
                .map(str::to_owned)
                .collect();
            calls.push((relative.clone(), words));
        }
    }
    calls
}

#[test]
fn every_chore_written_exists_and_every_chore_is_written_where_contributors_read() {
    let chores = chore_files();
    let calls = written_calls();
    assert!(calls.len() > 50, "only {} calls found", calls.len());
    let mut wrong = Vec::new();
    for (file, words) in &calls {
        let Some(name) = words.first() else { continue };
        // Placeholders, the tool's own options, and a chore's messages (`cargo xtask report: …`).
        if !name.starts_with(|c: char| c.is_ascii_lowercase()) || name.ends_with(':') {
            continue;
        }
        let name = name.trim_end_matches(['.', ':']);
        let Some((_, chore)) = chores.iter().find(|(chore, _)| chore == name) else {
            wrong.push(format!(
                "{file} runs `cargo xtask {name}`, which is no chore"
            ));
            continue;
        };
        // A word after the chore's name that reads as an operation or a report's name must be
        // one its help knows (numbers, paths, options and placeholders are arguments).
        if let Some(word) = words.get(1) {
            let word = word.trim_end_matches(['.', ':']);
            let is_operation = word.chars().next().is_some_and(|c| c.is_ascii_lowercase())
                && word.chars().all(|c| c.is_ascii_lowercase() || c == '-');
            let help: String = chore
                .lines()
                .take_while(|line| line.starts_with('#'))
                .collect::<Vec<_>>()
                .join("\n");
            let known = help
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
                .any(|known| known == word);
            if is_operation && !known {
                wrong.push(format!(
                    "{file} runs `cargo xtask {name} {word}`, which `cargo xtask {name} --help` does not know"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    for (chore, _) in &chores {
        let read = calls.iter().any(|(file, words)| {
            (file == "README.md" || file == ".ci/run" || file.starts_with("docs/"))
                && words.first().map(|word| word.trim_end_matches(['.', ':']))
                    == Some(chore.as_str())
        });
        assert!(read, "no page and no CI step names `cargo xtask {chore}`");
    }
}
