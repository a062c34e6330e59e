//! The list of what a report wrote (`manifest.txt`): every file and folder in it, so that a
//! run replacing it removes exactly those and nothing a user put beside them. A report folder is
//! replaced only when every entry anywhere under it is one its list names, as the same kind (a
//! file as a file, a folder as a folder, never a link); the first entry that is not is named.

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};

/// The list's file, at the top of a report.
pub(super) const MANIFEST: &str = "manifest.txt";

/// The list's first line, by which a report this program wrote is known.
const HEADER: &str = "# raytracer-grade report: every file and folder it wrote, replaced together";

/// The longest list read (a class of 10,000 submissions lists about 150,000 entries, 5 MB).
const MAX_MANIFEST_BYTES: u64 = 256 << 20;

/// What a report wrote: each entry's path (relative, `/` between names) and whether it is a
/// folder.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(super) struct Manifest {
    entries: BTreeMap<String, bool>,
}

/// Why a folder is not a report this program may replace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum NotAReport {
    /// It has no list, or not this program's.
    NoList,
    /// This entry (relative path) is not one the list names, or not as the kind it names.
    Stranger(String),
    /// It cannot be read.
    Unreadable(String),
}

/// Every entry under `folder`, not following links, in name order (a folder before what it
/// holds): its relative path, and `Some(is_folder)` for a plain file or folder, `None` for
/// anything else (a link, a pipe, a device).
fn walk(folder: &Path) -> std::io::Result<Vec<(String, Option<bool>)>> {
    let mut found = Vec::new();
    walk_into(folder, "", &mut found)?;
    Ok(found)
}

fn walk_into(
    folder: &Path,
    prefix: &str,
    found: &mut Vec<(String, Option<bool>)>,
) -> std::io::Result<()> {
    let mut entries: Vec<_> = std::fs::read_dir(folder)?.collect::<Result<_, _>>()?;
    entries.sort_by_key(std::fs::DirEntry::file_name);
    for entry in entries {
        let name = entry.file_name().to_string_lossy().into_owned();
        let relative = format!("{prefix}{name}");
        let kind = entry.file_type()?;
        let plain = if kind.is_dir() {
            Some(true)
        } else if kind.is_file() {
            Some(false)
        } else {
            None
        };
        found.push((relative.clone(), plain));
        if plain == Some(true) {
            walk_into(&entry.path(), &format!("{relative}/"), found)?;
        }
    }
    Ok(())
}

impl Manifest {
    /// Lists everything under `folder` (a report just made, which holds only what this run
    /// wrote) and writes the list into it.
    pub(super) fn write_for(folder: &Path) -> Result<Self, String> {
        let walked = walk(folder).map_err(|e| format!("{MANIFEST}: {e}"))?;
        let mut entries = BTreeMap::new();
        let mut text = format!("{HEADER}\n");
        for (relative, plain) in walked {
            let is_folder = plain == Some(true);
            text.push_str(&relative);
            text.push_str(if is_folder { "/\n" } else { "\n" });
            entries.insert(relative, is_folder);
        }
        entries.insert(MANIFEST.to_owned(), false);
        text.push_str(MANIFEST);
        text.push('\n');
        std::fs::write(folder.join(MANIFEST), text).map_err(|e| format!("{MANIFEST}: {e}"))?;
        Ok(Self { entries })
    }

    /// The list in `folder` (a report's, whatever else is there).
    pub(super) fn in_folder(folder: &Path) -> Result<Self, NotAReport> {
        let unreadable = |e: std::io::Error| NotAReport::Unreadable(e.to_string());
        match std::fs::symlink_metadata(folder.join(MANIFEST)) {
            Ok(metadata) if metadata.is_file() => {
                let file = std::fs::File::open(folder.join(MANIFEST)).map_err(unreadable)?;
                let mut text = String::new();
                file.take(MAX_MANIFEST_BYTES)
                    .read_to_string(&mut text)
                    .map_err(|_| NotAReport::NoList)?;
                Self::parse(&text).ok_or(NotAReport::NoList)
            }
            _ => Err(NotAReport::NoList),
        }
    }

    /// The list of the report in `folder`, where everything under it is an entry of that list.
    pub(super) fn of_report(folder: &Path) -> Result<Self, NotAReport> {
        let unreadable = |e: std::io::Error| NotAReport::Unreadable(e.to_string());
        let manifest = Self::in_folder(folder)?;
        for (relative, plain) in walk(folder).map_err(unreadable)? {
            match (manifest.entries.get(&relative), plain) {
                (Some(&listed), Some(is_folder)) if listed == is_folder => {}
                _ => return Err(NotAReport::Stranger(relative)),
            }
        }
        Ok(manifest)
    }

    /// The list in `text`, or `None` where it is not one this program wrote.
    fn parse(text: &str) -> Option<Self> {
        let mut lines = text.lines();
        if lines.next() != Some(HEADER) {
            return None;
        }
        let mut entries = BTreeMap::new();
        for line in lines.filter(|line| !line.is_empty()) {
            let (relative, is_folder) = match line.strip_suffix('/') {
                Some(folder) => (folder, true),
                None => (line, false),
            };
            // Only paths down into the report.
            if relative
                .split('/')
                .any(|name| name.is_empty() || name == "." || name == "..")
            {
                return None;
            }
            entries.insert(relative.to_owned(), is_folder);
        }
        Some(Self { entries })
    }

    /// Removes from `folder` the entries of this list that are still there as the kind listed
    /// (files, then folders deepest first, each only when empty), then `folder` itself when
    /// empty. Returns whether `folder` is gone: anything else put there is kept.
    pub(super) fn remove_listed(&self, folder: &Path) -> bool {
        let path = |relative: &str| -> PathBuf { folder.join(relative) };
        for (relative, _) in self.entries.iter().filter(|(_, is_folder)| !**is_folder) {
            let file = path(relative);
            if std::fs::symlink_metadata(&file).is_ok_and(|m| m.is_file()) {
                let _ = std::fs::remove_file(&file);
            }
        }
        // A folder's entries sort after it: the reverse order empties each before it.
        for (relative, _) in self.entries.iter().rev().filter(|(_, f)| **f) {
            let _ = std::fs::remove_dir(path(relative));
        }
        std::fs::remove_dir(folder).is_ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_list_leaving_the_report_is_not_read() {
        for bad in ["../x", "a/../../x", "/etc/passwd", "a//b", "./a"] {
            assert_eq!(
                Manifest::parse(&format!("{HEADER}\n{bad}\n")),
                None,
                "{bad}"
            );
        }
        assert!(Manifest::parse(&format!("{HEADER}\npages/\npages/0001.html\n")).is_some());
        assert_eq!(Manifest::parse("pages/\n"), None);
    }

    #[test]
    fn only_what_the_list_names_is_removed() {
        let root = tempfile::tempdir().unwrap();
        let report = root.path().join("report");
        std::fs::create_dir_all(report.join("pages")).unwrap();
        std::fs::write(report.join("pages/0001.html"), "page").unwrap();
        std::fs::write(report.join("index.html"), "table").unwrap();
        let listed = Manifest::write_for(&report).unwrap();
        assert_eq!(Manifest::of_report(&report), Ok(listed.clone()));
        std::fs::write(report.join("pages/notes.txt"), "mine").unwrap();
        assert_eq!(
            Manifest::of_report(&report),
            Err(NotAReport::Stranger("pages/notes.txt".to_owned()))
        );
        assert!(!listed.remove_listed(&report));
        assert_eq!(
            std::fs::read_to_string(report.join("pages/notes.txt")).unwrap(),
            "mine"
        );
        assert!(!report.join("index.html").exists());
        assert!(!report.join("pages/0001.html").exists());
        std::fs::remove_file(report.join("pages/notes.txt")).unwrap();
        assert!(listed.remove_listed(&report));
        assert!(!report.exists());
    }
}
