//! Unit tests of the scene parser: every keyword, the defaults, `MaterialIndex` scoping, nesting,
//! and each error kind with its line and column.

use glam::{DVec3, Vec3};

use std::fmt::Write as _;

use super::*;
use crate::scene::parse::SPHERES_PER_REPORT;

const CAMERA: &str = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n";

fn parse(text: &str) -> Scene {
    parse_scene(text).unwrap_or_else(|error| panic!("{error}\n{text}"))
}

/// The error of `text`, as (line, column, message).
fn fail(text: &str) -> (u32, u32, String) {
    let error = parse_scene(text).expect_err(text);
    (
        error.location.line,
        error.location.column,
        error.kind.to_string(),
    )
}

#[test]
fn every_keyword_of_the_format() {
    let scene = parse(
        "OrthographicCamera {\n center 1 2 3\n direction 0 0 -2\n up 0 3 0\n size 4.5\n}\n\
         Background { color 0.1 0.2 0.3 }\n\
         Materials {\n numMaterials 2\n PhongMaterial { diffuseColor 1 0 0 }\n Material { diffuseColor 0 1e-1 .5 }\n}\n\
         Group {\n numObjects 1\n MaterialIndex 1\n Sphere { center -1 -0.5 1e-3 radius 0.75 }\n}\n",
    );
    assert_eq!(
        scene.camera,
        OrthographicCamera {
            center_world: DVec3::new(1.0, 2.0, 3.0),
            direction_world: DVec3::new(0.0, 0.0, -2.0),
            up_world: DVec3::new(0.0, 3.0, 0.0),
            size_world: 4.5,
        }
    );
    assert_eq!(scene.background, Vec3::new(0.1, 0.2, 0.3));
    assert_eq!(
        scene.materials,
        vec![
            Material {
                diffuse_colour: Vec3::new(1.0, 0.0, 0.0)
            },
            Material {
                diffuse_colour: Vec3::new(0.0, 0.1, 0.5)
            }
        ]
    );
    assert_eq!(
        scene.spheres,
        vec![Sphere {
            center_world: DVec3::new(-1.0, -0.5, 1e-3),
            radius_world: 0.75,
            material: Some(1),
        }]
    );
}

#[test]
fn defaults_background_grey_material_white() {
    let scene = parse(&format!(
        "{CAMERA}Materials {{ numMaterials 1 PhongMaterial {{ }} }}\n\
         Group {{ numObjects 2 Sphere {{ center 0 0 0 radius 1 }} MaterialIndex 0 Sphere {{ center 1 0 0 radius 1 }} }}"
    ));
    assert_eq!(scene.background, DEFAULT_BACKGROUND);
    assert_eq!(scene.materials[0].diffuse_colour, Vec3::ONE);
    // A sphere before any MaterialIndex is white too.
    assert_eq!(scene.spheres[0].material, None);
    assert_eq!(scene.sphere_colour(&scene.spheres[0]), DEFAULT_DIFFUSE);
    assert_eq!(scene.sphere_colour(&scene.spheres[1]), Vec3::ONE);
}

#[test]
fn camera_only_scene_is_empty() {
    let scene = parse(CAMERA);
    assert!(scene.spheres.is_empty());
    assert!(scene.materials.is_empty());
    assert_eq!(scene.bounds(), None);
}

#[test]
fn material_index_applies_across_group_boundaries() {
    let scene = parse(&format!(
        "{CAMERA}Materials {{ numMaterials 3 Material {{ }} Material {{ }} Material {{ }} }}\n\
         Group {{ numObjects 3\n\
           MaterialIndex 2\n\
           Group {{ numObjects 2 Sphere {{ center 0 0 0 radius 1 }} MaterialIndex 1 Sphere {{ center 0 0 0 radius 1 }} }}\n\
           Sphere {{ center 0 0 0 radius 1 }}\n\
           Group {{ numObjects 1 Group {{ numObjects 1 Sphere {{ center 0 0 0 radius 1 }} }} }}\n\
         }}"
    ));
    let materials: Vec<_> = scene.spheres.iter().map(|s| s.material).collect();
    // The index set inside the nested group stays in effect after it closes.
    assert_eq!(materials, vec![Some(2), Some(1), Some(1), Some(1)]);
}

#[test]
fn nested_groups_flatten_in_file_order() {
    let scene = parse(&format!(
        "{CAMERA}Group {{ numObjects 2\n\
           Group {{ numObjects 2 Sphere {{ center 1 0 0 radius 1 }} Group {{ numObjects 1 Sphere {{ center 2 0 0 radius 1 }} }} }}\n\
           Sphere {{ center 3 0 0 radius 1 }}\n\
         }}"
    ));
    let xs: Vec<f64> = scene.spheres.iter().map(|s| s.center_world.x).collect();
    assert_eq!(xs, vec![1.0, 2.0, 3.0]);
}

#[test]
fn braces_need_no_surrounding_spaces_and_blocks_may_come_in_any_order() {
    let scene = parse(
        "Group{numObjects 1 MaterialIndex 0 Sphere{center 0 0 0 radius 1}}\n\
         Materials{numMaterials 1 PhongMaterial{diffuseColor 0 0 1}}\n\
         OrthographicCamera{center 0 0 10 direction 0 0 -1 up 0 1 0 size 5}",
    );
    assert_eq!(scene.sphere_colour(&scene.spheres[0]), Vec3::Z);
}

#[test]
fn missing_key_names_what_was_expected_and_found() {
    let text =
        format!("{CAMERA}Group {{\n  numObjects 1\n  Sphere {{\n    center 0 0 0\n    }}\n}}");
    assert_eq!(fail(&text), (6, 5, "expected 'radius', found '}'".into()));
}

#[test]
fn error_display_has_file_line_column() {
    let text =
        format!("{CAMERA}Group {{\n  numObjects 1\n  Sphere {{\n    center 0 0 0\n    }}\n}}");
    let error = parse_scene(&text).unwrap_err().in_file("scene1_02.txt");
    assert_eq!(
        error.to_string(),
        "scene1_02.txt:6:5: expected 'radius', found '}'"
    );
}

#[test]
fn unexpected_end_of_file() {
    let (line, column, message) = fail("OrthographicCamera {\n center 0 0");
    assert_eq!((line, column), (2, 12));
    assert_eq!(
        message,
        "expected a number (camera center), found end of file"
    );
}

#[test]
fn unsupported_keywords_are_named_with_their_line() {
    for keyword in [
        "PerspectiveCamera",
        "Lights",
        "Plane",
        "Triangle",
        "Transform",
        "TriangleMesh",
    ] {
        let (line, column, message) = fail(&format!("{CAMERA}\n{keyword} {{ }}"));
        assert_eq!((line, column), (3, 1), "{keyword}");
        assert!(
            message.starts_with(&format!("'{keyword}' is not supported")),
            "{message}"
        );
    }
    // Inside a group too.
    let (line, _, message) = fail(&format!(
        "{CAMERA}Group {{\n numObjects 1\n Plane {{ normal 0 1 0 offset 0 }}\n}}"
    ));
    assert_eq!(line, 4);
    assert!(message.contains("'Plane' is not supported"), "{message}");
    // And inside a material.
    let (_, _, message) = fail(&format!(
        "{CAMERA}Materials {{ numMaterials 1 PhongMaterial {{ diffuseColor 1 1 1 specularColor 1 1 1 }} }}"
    ));
    assert!(
        message.contains("'specularColor' is not supported"),
        "{message}"
    );
}

#[test]
fn unknown_word_at_top_level() {
    assert_eq!(
        fail("Camera { }"),
        (
            1,
            1,
            "expected 'OrthographicCamera', 'Background', 'Materials' or 'Group', found 'Camera'"
                .into()
        )
    );
}

#[test]
fn numbers_must_be_numbers_and_finite() {
    let (line, column, message) = fail("OrthographicCamera { center 0 zero 10 }");
    assert_eq!((line, column), (1, 31));
    assert_eq!(message, "expected a number (camera center), found 'zero'");
    for bad in ["inf", "NaN", "1e999", "-infinity"] {
        let (_, _, message) = fail(&format!(
            "{CAMERA}Group {{ numObjects 1 Sphere {{ center 0 0 0 radius {bad} }} }}"
        ));
        assert_eq!(
            message,
            format!("sphere radius must be a finite number, found '{bad}'")
        );
    }
    let (_, _, message) = fail(&format!(
        "{CAMERA}Group {{ numObjects 1 Sphere {{ center 0 0 1e200 radius 1 }} }}"
    ));
    assert_eq!(
        message,
        "sphere center must be at most 1e150 in magnitude, found '1e200'"
    );
    // Colours follow the same rule; beyond the 32-bit range they are kept as its largest value.
    let (_, _, message) = fail("Background { color 1e200 0 0 }");
    assert!(message.contains("at most 1e150 in magnitude"), "{message}");
    let scene = parse(&format!(
        "{CAMERA}Background {{ color 1e39 -1e39 1e-50 }}\nGroup {{ numObjects 0 }}"
    ));
    assert_eq!(scene.background.to_array(), [f32::MAX, -f32::MAX, 0.0]);
}

#[test]
fn counts_must_match_and_be_non_negative_integers() {
    let (line, column, message) = fail(&format!(
        "{CAMERA}Group {{\n numObjects 2\n Sphere {{ center 0 0 0 radius 1 }}\n}}"
    ));
    assert_eq!((line, column), (3, 13));
    assert_eq!(message, "Group declares 2 objects but holds 1");
    let (line, _, message) = fail(&format!(
        "{CAMERA}Materials {{\n numMaterials 1\n Material {{ }}\n Material {{ }}\n}}"
    ));
    assert_eq!(line, 3);
    assert_eq!(message, "Materials declares 1 materials but holds 2");
    for bad in ["-1", "1.5", "two", "99999999999999999999999"] {
        let (_, _, message) = fail(&format!("{CAMERA}Group {{ numObjects {bad} }}"));
        assert_eq!(
            message,
            format!("numObjects must be a non-negative integer, found '{bad}'")
        );
    }
    // A huge declared count allocates nothing: it simply does not match.
    let (_, _, message) = fail(&format!(
        "{CAMERA}Materials {{ numMaterials 99999999999999 }}"
    ));
    assert_eq!(
        message,
        "Materials declares 99999999999999 materials but holds 0"
    );
}

#[test]
fn material_index_must_be_in_range() {
    let (line, column, message) = fail(&format!(
        "{CAMERA}Materials {{ numMaterials 1 Material {{ }} }}\nGroup {{ numObjects 0\n MaterialIndex 1\n}}"
    ));
    assert_eq!((line, column), (4, 16));
    assert_eq!(
        message,
        "MaterialIndex 1 is out of range: the scene has 1 materials"
    );
}

#[test]
fn negative_radius_is_an_error_and_zero_is_a_point() {
    let (_, _, message) = fail(&format!(
        "{CAMERA}Group {{ numObjects 1 Sphere {{ center 0 0 0 radius -1 }} }}"
    ));
    assert_eq!(message, "sphere radius must be ≥ 0, found -1");
    let scene = parse(&format!(
        "{CAMERA}Group {{ numObjects 1 Sphere {{ center 0 0 0 radius 0 }} }}"
    ));
    assert_eq!(scene.spheres[0].radius_world, 0.0);
}

#[test]
fn camera_is_validated() {
    let camera = |direction: &str, up: &str, size: &str| {
        fail(&format!(
            "OrthographicCamera {{\n center 0 0 0\n direction {direction}\n up {up}\n size {size}\n}}"
        ))
    };
    assert_eq!(
        camera("0 0 0", "0 1 0", "5"),
        (3, 12, "camera direction must not be zero".into())
    );
    assert_eq!(
        camera("0 0 -1", "0 0 3", "5"),
        (
            4,
            2,
            "camera up must not be zero or parallel to the direction".into()
        )
    );
    assert_eq!(
        camera("0 0 -1", "0 1 0", "0"),
        (5, 7, "camera size must be > 0, found 0".into())
    );
    assert_eq!(
        fail("Background { color 0 0 0 }").2,
        "the scene has no OrthographicCamera block"
    );
}

#[test]
fn blocks_may_not_repeat() {
    let (line, column, message) = fail(&format!("{CAMERA}{CAMERA}"));
    assert_eq!((line, column), (2, 1));
    assert_eq!(
        message,
        "a second 'OrthographicCamera' block; a scene has at most one"
    );
}

#[test]
fn deep_nesting_is_capped() {
    let depth = MAX_GROUP_DEPTH + 1;
    let mut text = String::from(CAMERA);
    for _ in 0..depth {
        text.push_str("Group { numObjects 1 ");
    }
    let (_, _, message) = fail(&text);
    assert_eq!(
        message,
        format!("groups are nested deeper than {MAX_GROUP_DEPTH} levels")
    );
    // Exactly at the limit is fine.
    let mut text = String::from(CAMERA);
    for level in 0..MAX_GROUP_DEPTH {
        let count = usize::from(level + 1 < MAX_GROUP_DEPTH);
        let _ = write!(text, "Group {{ numObjects {count} ");
    }
    text.push_str(&"} ".repeat(MAX_GROUP_DEPTH));
    assert!(parse(&text).spheres.is_empty());
}

#[test]
fn binary_garbage_is_not_text() {
    let error = parse_scene_bytes(b"Group {\n \xff\xfe").unwrap_err();
    assert_eq!(error.kind, ParseErrorKind::NotText);
    assert_eq!((error.location.line, error.location.column), (2, 2));
    let (_, _, message) = fail("\u{1}\u{2}");
    assert!(
        message.starts_with("expected 'OrthographicCamera'"),
        "{message}"
    );
}

#[test]
fn empty_files_say_so() {
    for text in ["", "   \n\t\n"] {
        assert_eq!(
            fail(text),
            (
                1,
                1,
                "the file is empty: a scene needs at least an OrthographicCamera block".into()
            )
        );
    }
}

#[test]
fn long_tokens_are_shortened_in_messages() {
    let long = "x".repeat(500);
    let (_, _, message) = fail(&long);
    assert!(message.len() < 200, "{message}");
    assert!(message.contains('…'));
}

#[test]
fn load_scene_names_the_file() {
    let error = load_scene(std::path::Path::new("no/such/scene.txt")).unwrap_err();
    assert!(
        error.to_string().starts_with("no/such/scene.txt: "),
        "{error}"
    );
}

/// A scene of `count` spheres, all on one line when `one_line`.
fn many_spheres(count: usize, one_line: bool) -> String {
    let separator = if one_line { " " } else { "\n" };
    let mut text = format!("{CAMERA}Group {{ numObjects {count}{separator}");
    for i in 0..count {
        let _ = write!(text, "Sphere {{ center {i} 0 0 radius 1 }}{separator}");
    }
    text
}

#[test]
fn progress_rises_to_the_end_of_the_text() {
    let text = many_spheres(3 * SPHERES_PER_REPORT + 5, false) + "}\n";
    let reports = std::sync::Mutex::new(Vec::new());
    let scene = parse_scene_with_progress(&text, &|share| {
        reports.lock().map(|mut r| r.push(share)).ok();
    })
    .expect("valid scene");
    assert_eq!(scene.spheres.len(), 3 * SPHERES_PER_REPORT + 5);
    let reports = reports.into_inner().expect("not poisoned");
    assert_eq!(reports.len(), 3, "{reports:?}");
    assert!(reports.windows(2).all(|w| w[0] < w[1]), "{reports:?}");
    assert!(reports.iter().all(|&r| r > 0.0 && r <= 1.0), "{reports:?}");
}

#[test]
fn columns_on_a_very_long_line_are_exact() {
    // 200,000 spheres on one line, then a bad token: its column counts every character before it
    // (and the lexer stays linear: this would take minutes if each token rescanned its line).
    let mut text = many_spheres(200_000, true);
    let line_two_column = text.lines().nth(1).map_or(0, |line| line.chars().count()) + 1;
    text.push_str("Bogus");
    let (line, column, message) = fail(&text);
    assert_eq!(line, 2);
    assert_eq!(column as usize, line_two_column);
    assert!(message.contains("Bogus"), "{message}");
}
