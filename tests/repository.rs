//! The repository stands alone: a clone holds everything its code, manifests and pages name.
//! * no file names a path outside the repository (a sibling folder reached with `..`), or a
//!   specification it does not hold: the one it relies on is `docs/spec.md`;
//! * every repository path written in the source, the tests, the chores, the manifests and the
//!   pages (`src/…`, `docs/…`, `xtask/…`, …) exists, and so does every relative link of a
//!   Markdown page.
//!
//! Written paths are read as a newcomer would: a word that starts with one of the repository's
//! top-level folders. Words holding a placeholder (`NAME`, `NN`, `*`, `<…>`, `{…}`, `$`) name a
//! family of files, not one, and are not checked; nor are words holding `no_such` (a missing file
//! a test asks for on purpose).

use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Folders whose files are the project's text (not data, not third-party code, not builds).
const TEXT_FOLDERS: [&str; 11] = [
    "src", "tests", "examples", "benches", "bench", "xtask", "docs", "fuzz", "web", ".ci",
    ".github",
];
const TEXT_FILES: [&str; 6] = [
    "Cargo.toml",
    "README.md",
    "build.rs",
    "about.toml",
    "scenes/README.md",
    "scenes/assignment1.commands",
];
const TEXT_EXTENSIONS: [&str; 10] = [
    "rs", "md", "sh", "toml", "py", "mjs", "js", "html", "yml", "txt",
];
/// Folders under the text folders that hold data or third-party files, not the project's text.
const SKIPPED: [&str; 7] = [
    "tests/web/node_modules",
    "tests/corpus",
    "tests/reference",
    "tests/regressions",
    "fuzz/corpus",
    "fuzz/target",
    "fuzz/artifacts",
];
/// Paths a build or a script makes (ignored by `.gitignore`): named, but absent from a clone.
const MADE_BY_BUILDS: [&str; 4] = [
    "tests/web/node_modules",
    "fuzz/target",
    "fuzz/artifacts",
    "fuzz/coverage",
];

/// Top-level names a written repository path starts with.
const PATH_STARTS: [&str; 14] = [
    "src/",
    "tests/",
    "examples/",
    "benches/",
    "bench/",
    "scripts/",
    "xtask/",
    "docs/",
    "fuzz/",
    "web/",
    "scenes/",
    "assets/",
    ".ci/",
    ".github/",
];

fn text_files() -> Vec<PathBuf> {
    fn walk(folder: &Path, found: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(folder) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let relative = path
                .strip_prefix(root())
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            if SKIPPED.iter().any(|skipped| relative == *skipped) {
                continue;
            }
            if path.is_dir() {
                walk(&path, found);
            } else if path
                .extension()
                .is_some_and(|extension| TEXT_EXTENSIONS.iter().any(|e| extension == *e))
            {
                found.push(path);
            }
        }
    }
    let mut found: Vec<PathBuf> = TEXT_FILES.iter().map(|file| root().join(file)).collect();
    for folder in TEXT_FOLDERS {
        walk(&root().join(folder), &mut found);
    }
    found.sort();
    found
}

fn relative(path: &Path) -> String {
    path.strip_prefix(root())
        .unwrap()
        .to_string_lossy()
        .replace('\\', "/")
}

fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '/')
}

/// The repository paths written in `text`: words starting with a top-level folder, not preceded
/// by a character that would make them part of a longer path (`target/tests/…`, `/tmp/src/…`).
fn written_paths(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let bytes = text.as_bytes();
    for (start, _) in text.char_indices() {
        if start > 0 {
            let before = text[..start].chars().next_back().unwrap();
            if is_path_char(before) || before == '$' || before == '~' {
                continue;
            }
        }
        let Some(prefix) = PATH_STARTS.iter().find(|p| text[start..].starts_with(**p)) else {
            continue;
        };
        let end = text[start..]
            .char_indices()
            .find(|(_, c)| !is_path_char(*c))
            .map_or(text.len(), |(i, _)| start + i);
        // A placeholder, a glob or an interpolation right after the word: a family of files.
        if end < bytes.len() && matches!(bytes[end], b'*' | b'<' | b'{' | b'$' | b'[') {
            continue;
        }
        let word = text[start..end].trim_end_matches(['.', ',', '/']);
        // `no_such` names what must not exist (a test's missing file).
        if word.len() < prefix.len()
            || word.contains("no_such")
            || word.contains("NAME")
            || word.contains("NN")
            || word.contains("..")
        {
            continue;
        }
        found.push(word.to_owned());
    }
    found
}

/// The targets of the Markdown links `[text](target)` in `text` that point into the repository.
fn relative_links(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("](") {
        rest = &rest[at + 2..];
        let Some(end) = rest.find(')') else { break };
        let target = rest[..end].split('#').next().unwrap().trim();
        if !target.is_empty() && !target.contains("://") && !target.starts_with("mailto:") {
            found.push(target.to_owned());
        }
    }
    found
}

#[test]
fn no_file_names_a_path_outside_the_repository_or_a_specification_it_lacks() {
    // Spelled in pieces, so that this file does not name them itself.
    let sibling = ["..", "/shared"].concat();
    let bare_spec = ["SPEC", ".md"].concat();
    let mut offences = Vec::new();
    let files = text_files();
    assert!(files.len() > 100, "found only {} text files", files.len());
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for (number, line) in text.lines().enumerate() {
            if line.contains(&sibling) || line.contains(&bare_spec) {
                offences.push(format!(
                    "{}:{}: {}",
                    relative(file),
                    number + 1,
                    line.trim()
                ));
            }
        }
    }
    assert!(
        offences.is_empty(),
        "outside the repository:\n{}",
        offences.join("\n")
    );
    assert!(root().join("docs/spec.md").is_file());
}

#[test]
fn every_path_written_in_the_code_manifests_and_pages_exists() {
    let mut missing = Vec::new();
    let mut checked = 0;
    // This file names paths only to say what is skipped.
    for file in text_files()
        .into_iter()
        .filter(|f| !f.ends_with("tests/repository.rs"))
    {
        let text = std::fs::read_to_string(&file).unwrap();
        for (number, line) in text.lines().enumerate() {
            for path in written_paths(line) {
                checked += 1;
                // A path a build makes, a path from the root, from the page's own folder
                // (`fuzz/…` in docs/), or an example's name as cargo takes it
                // (`examples/generate`).
                let made = MADE_BY_BUILDS.iter().any(|made| path.starts_with(made));
                let found = made
                    || root().join(&path).exists()
                    || file.parent().unwrap().join(&path).exists()
                    || root().join(format!("{path}.rs")).exists();
                if !found {
                    missing.push(format!("{}:{}: {path}", relative(&file), number + 1));
                }
            }
        }
    }
    assert!(checked > 500, "checked only {checked} written paths");
    assert!(
        missing.is_empty(),
        "{} paths name nothing:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

#[test]
fn every_relative_link_of_a_markdown_page_exists() {
    let mut missing = Vec::new();
    let mut checked = 0;
    for file in text_files()
        .into_iter()
        .filter(|f| f.extension().is_some_and(|e| e == "md"))
    {
        let text = std::fs::read_to_string(&file).unwrap();
        let folder = file.parent().unwrap();
        for target in relative_links(&text) {
            checked += 1;
            if !folder.join(&target).exists() {
                missing.push(format!("{}: {target}", relative(&file)));
            }
        }
    }
    assert!(checked > 100, "checked only {checked} links");
    assert!(
        missing.is_empty(),
        "{} links lead nowhere:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

#[test]
fn the_path_reader_finds_paths_and_leaves_families_and_longer_paths() {
    assert_eq!(
        written_paths("see `src/lib.rs`, docs/spec.md. and xtask/chores/test.sh"),
        ["src/lib.rs", "docs/spec.md", "xtask/chores/test.sh"]
    );
    assert!(
        written_paths("target/tests/x.rs /tmp/src/a.rs docs/NAME.md docs/*.md $OUT/docs/a")
            .is_empty()
    );
    assert_eq!(
        relative_links("[a](viewer.md#x) [b](https://x.org) [c](../README.md)"),
        ["viewer.md", "../README.md"]
    );
}
