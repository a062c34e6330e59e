//! Every statement's sentence measured on pictures. A student acts on each sentence the diagnosis
//! prints, so each is a claim about their picture, tested like a figure: for every statement (a
//! known mistake or a fitted deviation) a case draws it — known mistakes with the project's
//! variant renderer (`oracle::mistaken`), fitted deviations with the student caster of
//! `examples/support/student.rs`, neither sharing code with the fit — has it diagnosed, reads the
//! claims its sentence makes (which way the picture moves and by how much, zoomed in or out, how
//! wide and tall a sphere is drawn, upside down or mirrored, near white or black, what colour
//! where nothing is hit, …) from the words themselves, and measures each on their picture beside
//! the exact one (centroids, second moments, flips, grey against t from a ray caster of this
//! file's own). Every measurement must also fail on the exact pictures, so none passes by
//! comparing nothing. The sentence is the one text the lines, the JSON, the viewer and the
//! grader give (`Deviation::explanation`); `a_statement_reads_the_same_in_the_lines_and_the_json`
//! checks that at the binary.

#[path = "common/statement_cases.rs"]
mod cases;
#[path = "common/claims.rs"]
mod claims;
#[path = "common/command.rs"]
mod command;
#[path = "common/compare_run.rs"]
mod compare_run;
#[path = "common/measure.rs"]
mod measure;
#[path = "common/shapes.rs"]
mod shapes;
#[path = "../examples/support/student.rs"]
mod student;

use rayon::prelude::*;
use raytracer::compare::judge::judge;
use raytracer::compare::{Deviation, Mistake, MistakeSet, Theirs};

use command::stderr;
use compare_run::{path, run, stdout, value};
use raytracer::oracle::mistaken::render_variant;
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::load_scene;

use cases::cases;
use claims::{Claim, claims_of};
use measure::measure;

/// The statements an answer makes, in full, in part or as alternatives.
fn every_statement(answer: &raytracer::compare::Diagnosis) -> Vec<Deviation> {
    let mut all: Vec<Deviation> = answer.stated().to_vec();
    all.extend_from_slice(answer.partial());
    for set in answer.alternatives() {
        all.extend_from_slice(set);
    }
    all
}

#[test]
fn every_statement_s_claims_hold_on_the_picture_it_is_said_of() {
    let cases = cases();
    let failures: Vec<String> = cases
        .par_iter()
        .map(|case| {
            let p = case.pictures();
            let range = Some(p.view.depth_range);
            let judged = judge(
                &p.scene,
                &p.exact,
                Theirs {
                    colour: Some(&p.colour),
                    depth: Some(&p.depth),
                },
                range,
            )
            .unwrap();
            let said = every_statement(&judged.diagnosis);
            let Some(statement) = said.iter().find(|s| s.word() == case.word) else {
                return vec![format!(
                    "{}: not said; the answer: {:?}",
                    case.word,
                    said.iter()
                        .map(Deviation::name_and_values)
                        .collect::<Vec<_>>()
                )];
            };
            let sentence = statement.explanation();
            let claims = claims_of(&sentence);
            let mut failures = Vec::new();
            if claims.is_empty() {
                failures.push(format!("{}: no claim read from \"{sentence}\"", case.word));
            }
            let exact = p.exact_as_theirs();
            for claim in &claims {
                if let Err(why) = measure(claim, &p) {
                    failures.push(format!(
                        "{} ({}): {claim:?} does not hold: {why}\n  \"{sentence}\"",
                        case.word,
                        statement.name_and_values()
                    ));
                }
                if !matches!(claim, Claim::SceneBackground(_)) && measure(claim, &exact).is_ok() {
                    failures.push(format!(
                        "{}: {claim:?} also holds on the exact pictures: it measures nothing",
                        case.word
                    ));
                }
            }
            failures
        })
        .flatten()
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The claim reader on sentences whose claims are known: a sentence that points the other way
/// reads the other way.
#[test]
fn the_claim_reader_reads_directions_amounts_and_colours() {
    assert_eq!(
        claims_of("so the picture is shifted half a pixel right and up: add ½"),
        [Claim::Shifted {
            right: 0.5,
            up: 0.5
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted half a pixel left and down: add ½"),
        [Claim::Shifted {
            right: -0.5,
            up: -0.5
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted 0.2 pixels right and 0.3 pixels down: give"),
        [Claim::Shifted {
            right: 0.2,
            up: -0.3
        }]
    );
    assert_eq!(
        claims_of("so the picture is shifted 1 pixel up: give"),
        [Claim::Shifted {
            right: 0.0,
            up: 1.0
        }]
    );
    assert_eq!(
        claims_of(
            "where no ray hits, the depth image is 76 76 76, your scene's background colour, instead"
        ),
        [Claim::DepthNoHit([76; 3]), Claim::SceneBackground([76; 3])]
    );
}

/// The sentence is one text: the lines print it after the statement's name and values, the JSON
/// gives it as the statement's `text`, and both are the library's `explanation`.
#[test]
fn a_statement_reads_the_same_in_the_lines_and_the_json() {
    let folder = tempfile::tempdir().unwrap();
    compare_run::write_mistaken(
        folder.path(),
        MistakeSet::of(&[Mistake::PixelCorners, Mistake::DepthReversed]),
        "png",
    );
    let lines = compare_run::stdout(&compare_run::compare(folder.path(), "png", &[]));
    let json = compare_run::compare(folder.path(), "png", &["-compare_format", "json"]);
    let answer: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let statements = answer["statements"].as_array().unwrap();
    assert_eq!(statements.len(), 2, "{lines}");
    for (statement, mistake) in statements
        .iter()
        .zip([Mistake::PixelCorners, Mistake::DepthReversed])
    {
        let text = statement["text"].as_str().unwrap();
        assert_eq!(text, Deviation::Word(mistake).explanation());
        assert!(
            lines.contains(&format!("diagnosis: {}: {text}\n", mistake.word())),
            "{lines}"
        );
    }
}

/// Every statement the answer can make has a case above: the fifteen known mistakes, and each
/// name of docs/compare-json.md's table of fitted statements.
#[test]
fn every_statement_has_a_case() {
    let table = std::fs::read_to_string(compare_run::path("docs/compare-json.md")).unwrap();
    let section = table
        .split("## The statements and their values")
        .nth(1)
        .unwrap();
    let mut names: Vec<String> = section
        .lines()
        .filter_map(|line| line.strip_prefix("| `"))
        .filter_map(|rest| rest.split('`').next())
        .map(str::to_owned)
        .collect();
    assert!(names.len() >= 16, "{names:?}");
    names.extend(Mistake::ALL.iter().map(|m| m.word().to_owned()));
    let covered: Vec<&str> = cases().iter().map(|c| c.word).collect();
    let missing: Vec<&String> = names
        .iter()
        .filter(|name| !covered.contains(&name.as_str()))
        .collect();
    assert!(missing.is_empty(), "statements without a case: {missing:?}");
}

/// A scene of more spheres than a model of their program is fitted to: the pixels are compared,
/// and the answer says why nothing more is said (in the lines and the JSON), with no fit begun.
#[test]
fn a_scene_too_large_to_fit_is_compared_and_says_why_no_model_was_fitted() {
    use raytracer::compare::diagnosis::MAX_FITTED_SPHERES;
    let folder = tempfile::tempdir().unwrap();
    let spheres = MAX_FITTED_SPHERES + 1;
    let scene = raytracer::oracle::random_scene(7, spheres);
    std::fs::write(
        folder.path().join("big.txt"),
        raytracer::scene::scene_to_text(&scene),
    )
    .unwrap();
    let made = run(
        folder.path(),
        &[
            "-input",
            "big.txt",
            "-size",
            "120",
            "120",
            "-output",
            "exact.tga",
        ],
    );
    assert_eq!(made.status.code(), Some(0), "{}", stderr(&made));
    // Their image: the exact one, its header saying the rows run top first (upside down).
    let mut tga = std::fs::read(folder.path().join("exact.tga")).unwrap();
    tga[17] ^= 0x20;
    std::fs::write(folder.path().join("theirs.tga"), tga).unwrap();
    let output = run(
        folder.path(),
        &["-input", "big.txt", "-compare_output", "theirs.tga"],
    );
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert!(value(&output, "colour_pixels_differing") != "0");
    assert_eq!(
        value(&output, "diagnosis"),
        format!(
            "none (no model fitted: the scene has {spheres} spheres, and a model of your program \
             is fitted to scenes of up to {MAX_FITTED_SPHERES} (beyond, the fit would take longer \
             than a comparison may): the pixels are compared, nothing is said of why they differ)"
        )
    );
    let json = run(
        folder.path(),
        &[
            "-input",
            "big.txt",
            "-compare_output",
            "theirs.tga",
            "-compare_format",
            "json",
        ],
    );
    let answer: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(answer["verdict"], "not-fitted");
    assert!(
        answer["not_fitted_because"]
            .as_str()
            .unwrap()
            .contains(&format!("{spheres} spheres"))
    );
}

/// A tie a single image cannot break says what would: a flipped depth image of scene1_02 alone
/// (its spheres sit alike flipped and mirrored) is `flipped-vertically | mirrored`, and the line
/// after names the course's scenes whose pictures the two draw differently; each named scene is
/// checked with the variant renderer (the two mistakes' images differ there), and each course
/// scene left out draws them alike.
#[test]
fn a_tie_says_which_images_would_tell_it_apart() {
    let folder = tempfile::tempdir().unwrap();
    let scene = load_scene(&path("scenes/scene1_02.txt")).unwrap();
    let view = View::of_camera(&scene.camera, 200, 200, DepthRange::new(8.0, 12.0));
    let (_, depth) = render_variant(&scene, &view, MistakeSet::of(&[Mistake::FlippedVertically]));
    depth.save(folder.path().join("depth.png")).unwrap();
    let scene_path = path("scenes/scene1_02.txt");
    let output = run(
        folder.path(),
        &[
            "-input",
            scene_path.to_str().unwrap(),
            "-compare_depth",
            "8",
            "12",
            "depth.png",
        ],
    );
    let text = stdout(&output);
    assert_eq!(
        value(&output, "diagnosis_ambiguous"),
        "flipped-vertically | mirrored",
        "{text}"
    );
    let tell = value(&output, "diagnosis_tell_apart");
    let named = tell
        .strip_prefix("your images of the course's ")
        .and_then(|rest| rest.split(" (their pictures differ there)").next())
        .unwrap_or_else(|| panic!("{tell}"));
    let named: Vec<&str> = named.split(", ").collect();
    assert!(!named.is_empty(), "{tell}");
    for line in std::fs::read_to_string(path("scenes/assignment1.commands"))
        .unwrap()
        .lines()
        .filter(|line| line.starts_with("raytracer"))
    {
        let words: Vec<&str> = line.split_whitespace().collect();
        let at = |flag: &str| words.iter().position(|w| *w == flag).unwrap() + 1;
        let name = words[at("-input")].trim_end_matches(".txt");
        let range = DepthRange::new(
            words[at("-depth")].parse().unwrap(),
            words[at("-depth") + 1].parse().unwrap(),
        );
        let scene = load_scene(&path(&format!("scenes/{name}.txt"))).unwrap();
        let view = View::of_camera(&scene.camera, 200, 200, range);
        let flipped = render_variant(&scene, &view, MistakeSet::of(&[Mistake::FlippedVertically]));
        let mirrored = render_variant(&scene, &view, MistakeSet::of(&[Mistake::Mirrored]));
        assert_eq!(
            named.contains(&name),
            flipped != mirrored,
            "{name}: said {tell}"
        );
    }
}
