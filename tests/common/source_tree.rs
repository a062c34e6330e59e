//! Reading the source tree for the structure checks (`tests/layout.rs`): the Rust files under a
//! folder, a file's module path, its code without its unit tests, and the module paths its
//! imports and paths name, groups and globs expanded.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

pub(crate) fn rust_files(folder: &Path, found: &mut Vec<PathBuf>) {
    files_ending(folder, "rs", found);
}

/// The files under `folder`, at any depth, whose extension is `extension`.
pub(crate) fn files_ending(folder: &Path, extension: &str, found: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(folder).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files_ending(&path, extension, found);
        } else if path.extension().is_some_and(|e| e == extension) {
            found.push(path);
        }
    }
}

pub(crate) fn source_files() -> Vec<PathBuf> {
    files_under(&["src"])
}

/// The Rust files under these folders of the project.
pub(crate) fn files_under(folders: &[&str]) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for folder in folders {
        let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join(folder);
        if folder.is_dir() {
            rust_files(&folder, &mut files);
        }
    }
    files.sort();
    files
}

/// `src/render/disc/raster.rs` → ["render", "disc", "raster"]; `mod.rs` names its folder.
pub(crate) fn module_path(file: &Path) -> Vec<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let relative = file.strip_prefix(&src).unwrap().with_extension("");
    let mut parts: Vec<String> = relative
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|last| last == "mod") {
        parts.pop();
    }
    parts
}

/// The code of a file without its unit tests (a `#[cfg(test)] mod tests { … }` block at the
/// end). A `mod tests;` declaration (the tests in a file of their own) cuts nothing: what
/// follows it is code.
pub(crate) fn without_tests(text: &str) -> &str {
    text.find("#[cfg(test)]\nmod tests {")
        .map_or(text, |start| &text[..start])
}

/// The modules a file refers to as `crate::a::b…`, as far as `depth` segments, grouped imports
/// (`crate::{a::b, c}`) included.
pub(crate) fn crate_references(text: &str, depth: usize) -> BTreeSet<Vec<String>> {
    let mut found = BTreeSet::new();
    for (start, _) in text.match_indices("crate::") {
        for mut parts in expanded_paths(&[], &text[start + "crate::".len()..]) {
            parts.truncate(depth);
            if !parts.is_empty() {
                found.insert(parts);
            }
        }
    }
    found
}

/// Every path a file in module `own` names from the crate's root or a parent (`crate::…`,
/// `super::…`, groups expanded), as a path from the crate's root: `super` and `self` resolved.
pub(crate) fn named_paths(text: &str, own: &[String]) -> Vec<Vec<String>> {
    let mut named = Vec::new();
    for (start, word) in text
        .match_indices("crate::")
        .chain(text.match_indices("super::"))
    {
        let before = text[..start].chars().last();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
            continue; // part of a longer path (super::super::, raytracer::crate…)
        }
        // A file's `super` is its parent module.
        let base = if word == "super::" {
            &own[..own.len().saturating_sub(1)]
        } else {
            &[]
        };
        for path in expanded_paths(base, &text[start + word.len()..]) {
            let mut resolved: Vec<String> = Vec::new();
            for part in path {
                match part.as_str() {
                    "super" => {
                        resolved.pop();
                    }
                    "self" => {}
                    _ => resolved.push(part),
                }
            }
            named.push(resolved);
        }
    }
    named
}

/// The longest start of `path` that is one of `modules` (empty when none is).
pub(crate) fn module_of(path: &[String], modules: &BTreeSet<Vec<String>>) -> Vec<String> {
    let mut module = path.to_vec();
    while !module.is_empty() && !modules.contains(&module) {
        module.pop();
    }
    module
}

/// The modules a file in module `own` uses: its [`named_paths`], each cut to the longest prefix
/// that is a module of the tree.
pub(crate) fn used_modules(
    text: &str,
    own: &[String],
    modules: &BTreeSet<Vec<String>>,
) -> BTreeSet<Vec<String>> {
    named_paths(text, own)
        .iter()
        .map(|path| module_of(path, modules))
        .filter(|module| !module.is_empty())
        .collect()
}

/// A project file's path from the project's folder, with `/` between its parts.
pub(crate) fn relative_name(file: &Path) -> String {
    file.strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap()
        .to_string_lossy()
        .replace('\\', "/")
}

/// The paths a `use` (or a path in code) starting at `rest` names, its groups expanded: `a::{b,
/// c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`; a glob ends in `*`.
pub(crate) fn expanded_paths(prefix: &[String], rest: &str) -> Vec<Vec<String>> {
    let mut parts = prefix.to_vec();
    let mut rest = rest.trim_start();
    loop {
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            break;
        }
        rest = &rest[name.len()..];
        parts.push(name);
        match rest.strip_prefix("::") {
            Some(more) => rest = more.trim_start(),
            None => return vec![parts],
        }
    }
    if let Some(group) = rest.strip_prefix('{') {
        let mut items = vec![String::new()];
        let mut nesting = 0;
        for c in group.chars() {
            match c {
                '{' => nesting += 1,
                '}' if nesting == 0 => break,
                '}' => nesting -= 1,
                ',' if nesting == 0 => {
                    items.push(String::new());
                    continue;
                }
                _ => {}
            }
            if let Some(item) = items.last_mut() {
                item.push(c);
            }
        }
        return items
            .iter()
            .filter(|item| !item.trim().is_empty())
            .flat_map(|item| expanded_paths(&parts, item))
            .collect();
    }
    if rest.starts_with('*') {
        parts.push("*".to_owned());
    }
    vec![parts]
}
