//! The pictures in docs/ cannot drift from what made them: each is written down in
//! docs/pictures.tsv by the command that made it (xtask/lib/pictures.sh), with its CRC-32 and
//! the names it shows. A picture that is not written down, or was replaced without its command
//! being run again, fails here; so does a name it shows that no longer exists (a scene file
//! renamed, the program's version moved on).

#[path = "common/source_tree.rs"]
#[allow(dead_code)] // the file walk alone
mod source_tree;

use std::collections::BTreeMap;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A row of docs/pictures.tsv.
struct Row {
    maker: String,
    crc: String,
    names: Vec<String>,
}

fn table() -> BTreeMap<String, Row> {
    let text = std::fs::read_to_string(root().join("docs/pictures.tsv")).unwrap();
    let mut rows = BTreeMap::new();
    for line in text.lines().filter(|line| !line.starts_with('#')) {
        let fields: Vec<&str> = line.split('\t').collect();
        let [picture, maker, crc, names] = fields[..] else {
            panic!("docs/pictures.tsv: not four fields: {line:?}");
        };
        let names = names
            .split(' ')
            .filter(|name| *name != "-" && !name.is_empty())
            .map(str::to_owned)
            .collect();
        let row = Row {
            maker: maker.to_owned(),
            crc: crc.to_owned(),
            names,
        };
        assert!(
            rows.insert(picture.to_owned(), row).is_none(),
            "docs/pictures.tsv: {picture} twice"
        );
    }
    rows
}

/// The pictures in docs/, at any depth, as `docs/…png` paths.
fn pictures() -> Vec<String> {
    let mut found = Vec::new();
    source_tree::files_ending(&root().join("docs"), "png", &mut found);
    found
        .iter()
        .map(|path| {
            let relative = path.strip_prefix(root()).unwrap();
            relative.to_string_lossy().replace('\\', "/")
        })
        .collect()
}

/// The chores `cargo xtask` knows (xtask/chores/NAME.sh).
fn chore_exists(name: &str) -> bool {
    root().join(format!("xtask/chores/{name}.sh")).is_file()
}

#[test]
fn every_picture_in_the_docs_is_written_down_by_the_command_that_made_it() {
    let rows = table();
    let pictures = pictures();
    assert!(pictures.len() >= 10, "pictures found: {pictures:?}");
    let mut problems = Vec::new();
    for picture in &pictures {
        let Some(row) = rows.get(picture) else {
            problems.push(format!("{picture}: not in docs/pictures.tsv"));
            continue;
        };
        let bytes = std::fs::read(root().join(picture)).unwrap();
        let crc = format!("{:08x}", crc32fast::hash(&bytes));
        if crc != row.crc {
            problems.push(format!(
                "{picture}: CRC-32 {crc}, written down {} (replaced without `{}`?)",
                row.crc, row.maker
            ));
        }
        let chore = row.maker.strip_prefix("cargo xtask ").unwrap_or("");
        if !chore_exists(chore.split(' ').next().unwrap_or("")) {
            problems.push(format!("{picture}: made by {:?}, no chore", row.maker));
        }
    }
    for picture in rows.keys() {
        if !pictures.contains(picture) {
            problems.push(format!("docs/pictures.tsv: {picture} is not in docs/"));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_names_a_picture_shows_exist() {
    // The program's version is this package's.
    let version = env!("CARGO_PKG_VERSION");
    let mut problems = Vec::new();
    let mut checked = 0;
    for (picture, row) in table() {
        for name in &row.names {
            checked += 1;
            if let Some(path) = name.strip_prefix("file:") {
                if !root().join(path).is_file() {
                    problems.push(format!("{picture} shows {path}: no such file"));
                }
            } else if let Some(shown) = name.strip_prefix("version:") {
                if shown != version {
                    problems.push(format!(
                        "{picture} shows raytracer {shown}; the program is {version}"
                    ));
                }
            } else {
                problems.push(format!("{picture}: {name:?} is neither file: nor version:"));
            }
        }
    }
    assert!(checked >= 3, "names checked: {checked}");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
