//! The diagnosis corpus (`tests/corpus/`): the output images of public C++ solutions of the
//! assignment and, per program, what its code does differently (`tests/corpus/programs.tsv`).
//! Each image is compared by the `raytracer` binary, as a student would compare it, and the
//! answer's statements are judged against the program's behaviours (`support/judge.rs`). Shared
//! by `tests/corpus.rs` (the rules) and `examples/diagnosis_report.rs` (`docs/diagnosis.md`);
//! the including file also includes `support/judge.rs` as `judge`.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// One program of the corpus.
pub(crate) struct Program {
    pub(crate) name: String,
    pub(crate) repository: String,
    pub(crate) commit: String,
    /// Behaviours that show on the corpus's command lines (`name` or `name=value`).
    pub(crate) visible: Vec<String>,
    /// Behaviours in the code that change no pixel on them, or a few.
    pub(crate) latent: Vec<String>,
    pub(crate) independence: String,
}

impl Program {
    /// Every behaviour, visible or latent.
    pub(crate) fn truth(&self) -> Vec<String> {
        self.visible.iter().chain(&self.latent).cloned().collect()
    }
}

/// One image of each program: its file, the scene, and the depth range when it is a depth image.
pub(crate) struct Image {
    pub(crate) file: &'static str,
    pub(crate) scene: &'static str,
    pub(crate) depth_range: Option<(&'static str, &'static str)>,
}

/// Text made once and kept for the run (the tables below are built once).
fn kept(text: String) -> &'static str {
    Box::leak(text.into_boxed_str())
}

/// The course's seven command lines at 200×200 (from `scenes/assignment1.commands`, the one
/// table of them; the programs' images are PNG) and scene1_02 at 203×61.
pub(crate) fn images() -> &'static [Image] {
    static IMAGES: OnceLock<Vec<Image>> = OnceLock::new();
    IMAGES.get_or_init(|| {
        let png = |name: &Path| kept(name.with_extension("png").to_string_lossy().into_owned());
        let mut images = Vec::new();
        for task in super::course::tasks() {
            let scene = kept(task.name());
            let depth_range = task
                .depth_words()
                .map(|[min, max]| (kept(min.to_owned()), kept(max.to_owned())));
            images.push(Image {
                file: png(task.colour.as_deref().unwrap()),
                scene,
                depth_range: None,
            });
            images.push(Image {
                file: png(&task.depth.as_ref().unwrap().1),
                scene,
                depth_range,
            });
        }
        let (min, max) = images
            .iter()
            .find_map(|image| image.depth_range.filter(|_| image.scene == "scene1_02"))
            .unwrap();
        images.push(Image {
            file: "output1_02_203x61.png",
            scene: "scene1_02",
            depth_range: None,
        });
        images.push(Image {
            file: "depth1_02_203x61.png",
            scene: "scene1_02",
            depth_range: Some((min, max)),
        });
        images
    })
}
/// What the comparison of one image answered (its `-compare_format json` document).
#[derive(Debug, Default)]
pub(crate) struct Outcome {
    /// The statements made in full, as names.
    pub(crate) stated: Vec<String>,
    /// The statements made in part, as names.
    pub(crate) partial: Vec<String>,
    /// The alternatives of a near tie, each a list of names.
    pub(crate) alternatives: Vec<Vec<String>>,
    /// Every statement with its values, as printed (`zoom 1.118`; partial ones marked).
    pub(crate) said: Vec<String>,
    /// `unexplained_pixels`.
    pub(crate) unexplained: u64,
    /// Pixels compared.
    pub(crate) pixels: u64,
    /// `match`.
    pub(crate) matched: bool,
    /// `verdict`.
    pub(crate) verdict: String,
}

impl Outcome {
    /// The judge's verdict against `truth`.
    pub(crate) fn judged(&self, truth: &[String]) -> super::judge::Verdict {
        super::judge::judge(
            self.matched,
            &[self.stated.clone(), self.partial.clone()].concat(),
            &self.alternatives,
            self.unexplained,
            self.pixels,
            truth,
        )
    }
}

/// The names and the printed form of a JSON list of statements.
fn statements(list: &serde_json::Value) -> Vec<(String, String)> {
    list.as_array()
        .into_iter()
        .flatten()
        .map(|statement| {
            let name = statement["name"].as_str().unwrap_or("?").to_owned();
            let values: Vec<String> = statement["values"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|v| match v {
                    serde_json::Value::Number(n) => {
                        let x = n.as_f64().unwrap_or(f64::NAN);
                        let text = format!("{x:.4}");
                        text.trim_end_matches('0').trim_end_matches('.').to_owned()
                    }
                    other => other.as_str().unwrap_or("?").to_owned(),
                })
                .collect();
            let printed = if values.is_empty() {
                name.clone()
            } else {
                format!("{name} {}", values.join(" "))
            };
            (name, printed)
        })
        .collect()
}

pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// The programs of `tests/corpus/programs.tsv`.
pub(crate) fn programs() -> Vec<Program> {
    let table =
        std::fs::read_to_string(root().join("tests/corpus/programs.tsv")).expect("programs.tsv");
    let list = |cell: &str| {
        cell.split(';')
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

/// Whether `program` wrote `image` (one program aborts on the non-square command line).
pub(crate) fn has(program: &Program, image: &Image) -> bool {
    files_of(program, image).0.exists()
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
    command.args(["-compare_format", "json"]);
    let output = command.output().expect("runs raytracer");
    let status = output.status.code();
    assert!(
        matches!(status, Some(0 | 3)),
        "{}/{}: exit {status:?}: {}",
        program.name,
        image.file,
        String::from_utf8_lossy(&output.stderr)
    );
    let answer: serde_json::Value =
        serde_json::from_slice(&output.stdout).expect("the answer is JSON");
    let (width, height) = image::image_dimensions(&file).expect("their image");
    let stated = statements(&answer["statements"]);
    let partial = statements(&answer["partial"]);
    let alternatives: Vec<Vec<(String, String)>> = answer["alternatives"]
        .as_array()
        .into_iter()
        .flatten()
        .map(statements)
        .collect();
    let mut said: Vec<String> = stated.iter().map(|s| s.1.clone()).collect();
    said.extend(partial.iter().map(|s| format!("{} (in part)", s.1)));
    if !alternatives.is_empty() {
        let sets: Vec<String> = alternatives
            .iter()
            .map(|set| {
                set.iter()
                    .map(|s| s.1.clone())
                    .collect::<Vec<_>>()
                    .join(" + ")
            })
            .collect();
        said.push(format!("one of: {}", sets.join(" \\| ")));
    }
    Outcome {
        stated: stated.into_iter().map(|s| s.0).collect(),
        partial: partial.into_iter().map(|s| s.0).collect(),
        alternatives: alternatives
            .into_iter()
            .map(|set| set.into_iter().map(|s| s.0).collect())
            .collect(),
        said,
        unexplained: answer["unexplained_pixels"].as_u64().unwrap_or(0),
        pixels: u64::from(width) * u64::from(height),
        matched: answer["match"].as_bool().unwrap_or(false),
        verdict: answer["verdict"].as_str().unwrap_or("?").to_owned(),
    }
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
