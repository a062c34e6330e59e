//! A class's submissions: one folder per student in the submissions folder, each holding the
//! images the assignment's lines name. Submissions are untrusted: a name is found whatever its
//! letter case and with `.tga` or `.png` (the difference is said), and only regular files inside
//! the folder are read — a link is never followed, a named pipe or device never opened.

use std::ffi::OsString;
use std::fmt::Write as _;

use image::RgbImage;

use crate::compare::their_image::{TheirImageError, read_their_file_sized};
use crate::platform::files::open_regular_file;
use std::path::{Path, PathBuf};

/// One entry of the submissions folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Submission {
    /// The folder's name, as the file system has it (shown escaped; never used for a report's
    /// file name).
    pub name: String,
    /// The folder.
    pub folder: PathBuf,
    /// Why it is not graded (a link, not a folder), when it is not.
    pub skipped: Option<String>,
}

/// The submissions in `folder`, by name.
pub fn list_submissions(folder: &Path) -> std::io::Result<Vec<Submission>> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(folder)? {
        let entry = entry?;
        let path = entry.path();
        let name = shown_name(&entry.file_name());
        if name.starts_with('.') {
            continue;
        }
        let kind = entry.file_type()?;
        let skipped = if kind.is_symlink() {
            Some("a link: not followed".to_owned())
        } else if kind.is_dir() {
            None
        } else {
            // Files beside the folders (a class list, an archive) are not submissions.
            continue;
        };
        found.push(Submission {
            name,
            folder: path,
            skipped,
        });
    }
    found.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(found)
}

/// Where a named image was found in a submission.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Found {
    /// A regular file; `renamed` when its name differs from the one asked for (letter case or
    /// `.tga`/`.png`).
    File {
        /// The file.
        path: PathBuf,
        /// Its name in the submission, when not the name asked for.
        renamed: Option<String>,
    },
    /// Nothing by that name.
    Missing,
    /// Something by that name that is not read, and why.
    NotRead {
        /// Its name in the submission.
        name: String,
        /// Why it is not read.
        why: String,
    },
}

/// Finds `wanted` (a relative path: its folders exactly, its file name with letter case and
/// `.tga`/`.png` forgiven) in `folder`. The exact name is taken first, then a letter-case
/// variant, then the name with the other extension (each the first in byte order where several
/// are there: `OUTPUT1_01.TGA` before `Output1_01.tga`); never a file another of the
/// assignment's lines names (`claimed`: a `.tga` line does not grade the `.png` another names).
pub fn find_image(folder: &Path, wanted: &Path, claimed: &[PathBuf]) -> Found {
    let Some(file_name) = wanted.file_name() else {
        return Found::Missing;
    };
    let mut place = folder.to_path_buf();
    let unreadable = |error: std::io::Error| Found::NotRead {
        name: wanted.display().to_string(),
        why: format!("its folder cannot be read: {error}"),
    };
    if let Some(parent) = wanted.parent() {
        for part in parent.components() {
            place.push(part);
            match std::fs::symlink_metadata(&place) {
                Ok(metadata) if metadata.is_dir() => {}
                Ok(_) => {
                    return Found::NotRead {
                        name: wanted.display().to_string(),
                        why: format!(
                            "'{}' is not a folder (links are not followed)",
                            shown_name(part.as_os_str())
                        ),
                    };
                }
                Err(error) if error.kind() == std::io::ErrorKind::NotFound => {
                    return Found::Missing;
                }
                Err(error) => return unreadable(error),
            }
        }
    }
    let entries = match std::fs::read_dir(&place) {
        Ok(entries) => entries,
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => return Found::Missing,
        Err(error) => return unreadable(error),
    };
    let mut names: Vec<OsString> = entries
        .filter_map(|e| e.ok().map(|e| e.file_name()))
        .collect();
    names.sort();
    // Another line's file, by its name in any letter case.
    let others: Vec<String> = claimed
        .iter()
        .filter(|other| other.parent() == wanted.parent())
        .filter_map(|other| other.file_name())
        .map(|other| other.to_string_lossy().to_lowercase())
        .filter(|other| *other != file_name.to_string_lossy().to_lowercase())
        .collect();
    names.retain(|name| {
        name == file_name || !others.contains(&name.to_string_lossy().to_lowercase())
    });
    let wanted_text = file_name.to_string_lossy();
    let stem_of = |name: &str| -> String {
        let lower = name.to_lowercase();
        for extension in [".tga", ".png"] {
            if let Some(stem) = lower.strip_suffix(extension) {
                return stem.to_owned();
            }
        }
        lower
    };
    let wanted_stem = stem_of(&wanted_text);
    let is_image = |name: &str| stem_of(name) != name.to_lowercase();
    // The exact name first, then its letter case, then the other extension.
    let chosen = names
        .iter()
        .find(|name| name.as_os_str() == file_name)
        .or_else(|| {
            names
                .iter()
                .find(|name| name.to_string_lossy().to_lowercase() == wanted_text.to_lowercase())
        })
        .or_else(|| {
            let mut others: Vec<&OsString> = names
                .iter()
                .filter(|name| {
                    let name = name.to_string_lossy();
                    is_image(&name) && stem_of(&name) == wanted_stem
                })
                .collect();
            others.sort();
            others.first().copied()
        });
    let Some(chosen) = chosen else {
        return Found::Missing;
    };
    let path = place.join(chosen);
    let name = shown_name(chosen);
    match std::fs::symlink_metadata(&path) {
        Ok(metadata) if metadata.file_type().is_symlink() => Found::NotRead {
            name,
            why: "a link: not followed".to_owned(),
        },
        Ok(metadata) if !metadata.is_file() => Found::NotRead {
            name,
            why: "not a regular file".to_owned(),
        },
        Ok(_) => Found::File {
            renamed: (chosen.as_os_str() != file_name).then_some(name),
            path,
        },
        Err(error) => Found::NotRead {
            name,
            why: error.to_string(),
        },
    }
}

/// A file name as the report shows it: as it is where it is text; where it is not (bytes that
/// are not UTF-8, on Unix), each such byte as `\xNN`, so that two such names never look alike.
pub fn shown_name(name: &std::ffi::OsStr) -> String {
    if let Some(text) = name.to_str() {
        return text.to_owned();
    }
    let mut shown = String::new();
    for chunk in name.as_encoded_bytes().utf8_chunks() {
        shown.push_str(chunk.valid());
        for byte in chunk.invalid() {
            let _ = write!(shown, "\\x{byte:02X}");
        }
    }
    shown
}

/// Why a found image was not read: another size (from its header), or unreadable.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum NotRead {
    /// Its size, and the size asked for.
    WrongSize {
        /// Its size.
        found: (u32, u32),
        /// The size asked for.
        expected: (u32, u32),
    },
    /// Why it cannot be read.
    Unreadable(String),
}

/// Reads a submission's image, which must be `size_px`.
pub(super) fn read_found_image(path: &Path, size_px: (u32, u32)) -> Result<RgbImage, NotRead> {
    // Opened once, as checked: a file swapped for a link or a pipe since it was found is
    // refused on the handle, never read through.
    let file = open_regular_file(path).map_err(|error| NotRead::Unreadable(error.to_string()))?;
    if file.metadata().is_ok_and(|m| m.len() == 0) {
        return Err(NotRead::Unreadable("an empty file".to_owned()));
    }
    // Another size is said from the header, its pixels never decoded.
    match read_their_file_sized(file, path, Some(size_px)) {
        Err(TheirImageError::OtherSize {
            found, expected, ..
        }) => Err(NotRead::WrongSize { found, expected }),
        Err(error) => Err(NotRead::Unreadable(error.reason())),
        Ok(image) if image.dimensions() != size_px => Err(NotRead::WrongSize {
            found: image.dimensions(),
            expected: size_px,
        }),
        Ok(image) => Ok(image),
    }
}
