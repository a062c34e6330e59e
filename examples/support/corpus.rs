//! The diagnosis corpus (`tests/corpus/`): the output images of public C++ solutions of the
//! assignment and, per program, the mistakes its code makes (`tests/corpus/programs.tsv`). Each
//! image is compared by the `raytracer` binary, as a student would compare it, and what the
//! diagnosis named is judged against the program's mistakes. Shared by `tests/corpus.rs` (the
//! rules) and `examples/diagnosis_report.rs` (`docs/diagnosis.md`).

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// One program of the corpus.
pub(crate) struct Program {
    pub(crate) name: String,
    pub(crate) repository: String,
    pub(crate) commit: String,
    /// Mistakes that show on the corpus's command lines.
    pub(crate) visible: Vec<String>,
    /// Mistakes in the code that change no pixel on them.
    pub(crate) latent: Vec<String>,
    pub(crate) independence: String,
}

impl Program {
    /// Whether `word` is one of the program's mistakes.
    pub(crate) fn makes(&self, word: &str) -> bool {
        self.visible.iter().chain(&self.latent).any(|m| m == word)
    }
}

/// One image of each program: its file, the scene, and the depth range when it is a depth image.
pub(crate) struct Image {
    pub(crate) file: &'static str,
    pub(crate) scene: &'static str,
    pub(crate) depth_range: Option<(&'static str, &'static str)>,
}

const fn colour(file: &'static str, scene: &'static str) -> Image {
    Image {
        file,
        scene,
        depth_range: None,
    }
}

const fn depth(
    file: &'static str,
    scene: &'static str,
    min: &'static str,
    max: &'static str,
) -> Image {
    Image {
        file,
        scene,
        depth_range: Some((min, max)),
    }
}

/// The course's seven command lines at 200×200 and scene1_02 at 203×61.
pub(crate) const IMAGES: [Image; 16] = [
    colour("output1_01.png", "scene1_01"),
    depth("depth1_01.png", "scene1_01", "9", "10"),
    colour("output1_02.png", "scene1_02"),
    depth("depth1_02.png", "scene1_02", "8", "12"),
    colour("output1_03.png", "scene1_03"),
    depth("depth1_03.png", "scene1_03", "8", "12"),
    colour("output1_04.png", "scene1_04"),
    depth("depth1_04.png", "scene1_04", "12", "17"),
    colour("output1_05.png", "scene1_05"),
    depth("depth1_05.png", "scene1_05", "14.5", "19.5"),
    colour("output1_06.png", "scene1_06"),
    depth("depth1_06.png", "scene1_06", "3", "7"),
    colour("output1_07.png", "scene1_07"),
    depth("depth1_07.png", "scene1_07", "-2", "2"),
    colour("output1_02_203x61.png", "scene1_02"),
    depth("depth1_02_203x61.png", "scene1_02", "8", "12"),
];

/// What the comparison of one image printed.
#[derive(Debug, Default)]
pub(crate) struct Outcome {
    /// `diagnosis:` words (not `none`).
    pub(crate) named: Vec<String>,
    /// `diagnosis_partial:` words.
    pub(crate) partial: Vec<String>,
    /// A `diagnosis_ambiguous:` line.
    pub(crate) ambiguous: Option<String>,
    /// `unexplained_pixels:`, when printed.
    pub(crate) unexplained: Option<u64>,
    /// `match: yes`.
    pub(crate) matched: bool,
}

impl Outcome {
    /// Every word the comparison put forward, in full or in part.
    pub(crate) fn words(&self) -> impl Iterator<Item = &String> {
        self.named.iter().chain(&self.partial)
    }
}

pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// The programs of `tests/corpus/programs.tsv`.
pub(crate) fn programs() -> Vec<Program> {
    let table =
        std::fs::read_to_string(root().join("tests/corpus/programs.tsv")).expect("programs.tsv");
    let list = |cell: &str| {
        cell.split(',')
            .filter(|w| !w.is_empty())
            .map(str::to_owned)
            .collect()
    };
    table
        .lines()
        .filter(|line| !line.starts_with('#') && !line.starts_with("program\t"))
        .map(|line| {
            let cells: Vec<&str> = line.split('\t').collect();
            Program {
                name: cells[0].to_owned(),
                repository: cells[1].to_owned(),
                commit: cells[2].to_owned(),
                visible: list(cells[3]),
                latent: list(cells[4]),
                independence: cells[5].to_owned(),
            }
        })
        .collect()
}

/// The image file of `program` and the scene file it was rendered from.
fn files_of(program: &Program, image: &Image) -> (PathBuf, PathBuf) {
    let root = root();
    let file = root
        .join("tests/corpus")
        .join(&program.name)
        .join(image.file);
    (
        file,
        root.join("scenes").join(format!("{}.txt", image.scene)),
    )
}

/// Compares `program`'s `image` with the `raytracer` binary at `binary`.
pub(crate) fn compare(binary: &Path, program: &Program, image: &Image) -> Outcome {
    let (file, scene) = files_of(program, image);
    let mut command = Command::new(binary);
    command.arg("-input").arg(&scene);
    match image.depth_range {
        None => command.arg("-compare_output").arg(&file),
        Some((min, max)) => command.args(["-compare_depth", min, max]).arg(&file),
    };
    let output = command.output().expect("runs raytracer");
    let status = output.status.code();
    assert!(
        matches!(status, Some(0 | 3)),
        "{}/{}: exit {status:?}: {}",
        program.name,
        image.file,
        String::from_utf8_lossy(&output.stderr)
    );
    let mut outcome = Outcome::default();
    for line in String::from_utf8_lossy(&output.stdout).lines() {
        if let Some(word) = line.strip_prefix("diagnosis: ") {
            if word != "none" {
                outcome.named.push(word.to_owned());
            }
        } else if let Some(word) = line.strip_prefix("diagnosis_partial: ") {
            outcome.partial.push(word.to_owned());
        } else if let Some(sets) = line.strip_prefix("diagnosis_ambiguous: ") {
            outcome.ambiguous = Some(sets.to_owned());
        } else if let Some(count) = line.strip_prefix("unexplained_pixels: ") {
            outcome.unexplained = count.parse().ok();
        } else if line == "match: yes" {
            outcome.matched = true;
        }
    }
    outcome
}

/// The depth range the binary reads back from a depth image given without one
/// (`depth_range_inferred:`), as printed, or `none` when it refuses the image.
pub(crate) fn infer_range(binary: &Path, program: &Program, image: &Image) -> String {
    let (file, scene) = files_of(program, image);
    let output = Command::new(binary)
        .arg("-input")
        .arg(&scene)
        .arg("-compare_depth")
        .arg(&file)
        .output()
        .expect("runs raytracer");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .find_map(|line| line.strip_prefix("depth_range_inferred: "))
        .unwrap_or("none")
        .to_owned()
}
