//! What makes two paths the same file: the device and inode of a file that exists, else its
//! canonical folder and its name. So `out.tga`, `./out.tga` and `sub/../out.tga` are one file, and
//! so are a file, its symbolic links and its hard links.

use std::os::unix::fs::MetadataExt as _;
use std::path::{Path, PathBuf};

use super::atomic::folder_of;

/// A file's identity; `None` when not even its folder exists.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum FileIdentity {
    /// A file that exists.
    Existing {
        /// Its device.
        device: u64,
        /// Its inode.
        inode: u64,
    },
    /// A file to be created: its canonical folder joined with its name.
    New(PathBuf),
}

/// The identity of the file `path` names.
pub(crate) fn identity(path: &Path) -> Option<FileIdentity> {
    if let Ok(metadata) = std::fs::metadata(path) {
        return Some(FileIdentity::Existing {
            device: metadata.dev(),
            inode: metadata.ino(),
        });
    }
    let folder = std::fs::canonicalize(folder_of(path)).ok()?;
    Some(FileIdentity::New(folder.join(path.file_name()?)))
}

/// Whether `a` and `b` name the same file.
pub(crate) fn same_file(a: &Path, b: &Path) -> bool {
    matches!((identity(a), identity(b)), (Some(x), Some(y)) if x == y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_and_links_of_one_file_are_the_same_file() {
        let folder = tempfile::tempdir().unwrap();
        let file = folder.path().join("a.txt");
        std::fs::write(&file, b"x").unwrap();
        std::fs::create_dir(folder.path().join("sub")).unwrap();
        std::os::unix::fs::symlink(&file, folder.path().join("link")).unwrap();
        std::fs::hard_link(&file, folder.path().join("hard")).unwrap();
        for other in ["sub/../a.txt", "./a.txt", "link", "hard"] {
            assert!(same_file(&file, &folder.path().join(other)), "{other}");
        }
        // Files that do not exist yet: by folder and name.
        let new = folder.path().join("new.png");
        assert!(same_file(&new, &folder.path().join("sub/../new.png")));
        assert!(!same_file(&new, &folder.path().join("other.png")));
        assert!(!same_file(&file, &new));
    }
}
