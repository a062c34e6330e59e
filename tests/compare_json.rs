//! `-compare_format json` through the real binary: the answer as one JSON document
//! (`docs/compare-json.md`), the same as the lines it replaces, and the flag's usage errors.

#[path = "common/command.rs"]
mod command;
#[path = "common/compare_run.rs"]
mod compare_run;

use command::stderr;
use compare_run::{SCENE, compare, diagnosis, path, run, stdout, value, write_mistaken};
use raytracer::compare::{Mistake, MistakeSet};

/// `-compare_format json` prints the answer as one JSON document (docs/compare-json.md): the
/// same verdict, statements and counts as the lines, with the statements' values as numbers.
#[test]
fn the_answer_as_json_carries_the_statements_and_their_values() {
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(
        folder.path(),
        MistakeSet::of(&[Mistake::PixelCorners, Mistake::DepthReversed]),
        "png",
    );
    let lines = compare(folder.path(), "png", &[]);
    let json = compare(folder.path(), "png", &["-compare_format", "json"]);
    assert_eq!(json.status.code(), Some(3), "{}", stderr(&json));
    let answer: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(answer["format"], "raytracer-compare");
    assert_eq!(answer["version"], 2);
    assert_eq!(answer["match"], false);
    assert_eq!(answer["verdict"], "explained");
    let names: Vec<&str> = answer["statements"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, diagnosis(&lines));
    assert_eq!(names, ["pixel-corners", "depth-reversed"]);
    assert_eq!(answer["statements"][0]["known_mistake"], true);
    assert!(
        answer["statements"][0]["text"]
            .as_str()
            .unwrap()
            .contains("pixel corners")
    );
    assert_eq!(
        answer["unexplained_pixels"].as_u64().unwrap().to_string(),
        value(&lines, "unexplained_pixels")
    );
    assert_eq!(
        answer["depth"]["pixels_differing"]
            .as_u64()
            .unwrap()
            .to_string(),
        value(&lines, "depth_pixels_differing")
    );
    // The range given is said as given, and nothing is said to be inferred.
    assert_eq!(answer["depth_range_given"], serde_json::json!([6.0, 10.0]));
    assert_eq!(answer["depth_range_inferred"], serde_json::Value::Null);
    assert_eq!(value(&lines, "depth_range_given"), "6 10");
    assert!(!stdout(&lines).contains("depth_range_inferred"));
}

/// The format flag is checked like any other: an unknown format and a format with nothing to
/// compare are usage errors (exit 2) that write nothing.
#[test]
fn a_bad_compare_format_is_a_usage_error() {
    let folder = tempfile::tempdir().unwrap();
    write_mistaken(
        folder.path(),
        MistakeSet::of(&[Mistake::PixelCorners]),
        "png",
    );
    let output = compare(folder.path(), "png", &["-compare_format", "yaml"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("-compare_format: expected lines or json, found 'yaml'"));
    let scene = path(SCENE);
    let output = run(
        folder.path(),
        &[
            "-input",
            scene.to_str().unwrap(),
            "-output",
            "out.png",
            "-compare_format",
            "json",
        ],
    );
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("-compare_format needs -compare_output"),
        "{}",
        stderr(&output)
    );
    assert!(!folder.path().join("out.png").exists());
}
