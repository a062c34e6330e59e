//! Unit tests of `atomic` (a file of their own, so that the module stays short).

use super::*;

fn names_in(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn a_failure_while_staging_replaces_nothing_and_leaves_no_temporary() {
    let folder = tempfile::tempdir().unwrap();
    let first = folder.path().join("first.txt");
    let second = folder.path().join("second.txt");
    std::fs::write(&first, b"old first").unwrap();
    std::fs::write(&second, b"old second").unwrap();
    let mut set = FileSet::new();
    set.stage_bytes(&first, b"new first").unwrap();
    // The second file's content fails half-way (as a full disk would).
    let failed = set.stage(&second, |out| {
        out.write_all(b"half").map_err(|e| io_error(&second, e))?;
        Err(io_error(&second, std::io::Error::other("disk full")))
    });
    assert!(failed.is_err());
    drop(set);
    assert_eq!(std::fs::read(&first).unwrap(), b"old first");
    assert_eq!(std::fs::read(&second).unwrap(), b"old second");
    assert_eq!(names_in(folder.path()), ["first.txt", "second.txt"]);
}

#[test]
fn a_commit_replaces_every_file_and_removes_the_temporaries() {
    let folder = tempfile::tempdir().unwrap();
    let first = folder.path().join("first.txt");
    std::fs::write(&first, b"old").unwrap();
    let mut set = FileSet::new();
    set.stage_bytes(&first, b"new first").unwrap();
    set.stage_bytes(&folder.path().join("second.txt"), b"new second")
        .unwrap();
    let written = set.commit().unwrap();
    assert_eq!(written.len(), 2);
    assert_eq!(std::fs::read(&first).unwrap(), b"new first");
    assert_eq!(names_in(folder.path()), ["first.txt", "second.txt"]);
    assert!(
        open_temporaries()
            .iter()
            .all(|p| !p.starts_with(folder.path()))
    );
}

#[test]
fn temporaries_are_registered_while_written_and_removed_when_dropped() {
    // (The removal on a signal goes through this registry; tests/robustness.rs sends the
    // signal. Removing every registered file here would take other tests' files too.)
    let folder = tempfile::tempdir().unwrap();
    let temporary = Temporary::create(folder.path(), 0o666).unwrap();
    assert_eq!(names_in(folder.path()).len(), 1);
    assert!(open_temporaries().contains(&temporary.path));
    let path = temporary.path.clone();
    drop(temporary);
    assert!(!open_temporaries().contains(&path));
    assert!(names_in(folder.path()).is_empty());
}
