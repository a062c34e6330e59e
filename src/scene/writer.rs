//! Writing a [`Scene`] back as scene-file text: what "save view as scene" and exports write, and
//! how generated test scenes become files.

use std::fmt::Write as _;

use glam::{DVec3, Vec3};

use super::model::Scene;

/// The scene as scene-file text (numbers written exactly: Rust's shortest round-trip form).
pub fn scene_to_text(scene: &Scene) -> String {
    let mut text = String::new();
    let camera = &scene.camera;
    let v = |v: DVec3| format!("{} {} {}", v.x, v.y, v.z);
    let c = |c: Vec3| format!("{} {} {}", c.x, c.y, c.z);
    // Writing to a String cannot fail.
    let _ = write!(
        text,
        "OrthographicCamera {{\n    center {}\n    direction {}\n    up {}\n    size {}\n}}\n\n\
         Background {{ color {} }}\n\nMaterials {{\n    numMaterials {}\n",
        v(camera.center_world),
        v(camera.direction_world),
        v(camera.up_world),
        camera.size_world,
        c(scene.background),
        scene.materials.len()
    );
    for material in &scene.materials {
        let _ = writeln!(
            text,
            "    PhongMaterial {{ diffuseColor {} }}",
            c(material.diffuse_colour)
        );
    }
    let _ = write!(
        text,
        "}}\n\nGroup {{\n    numObjects {}\n",
        scene.spheres.len()
    );
    let mut current = None;
    for sphere in &scene.spheres {
        if sphere.material != current
            && let Some(index) = sphere.material
        {
            let _ = writeln!(text, "    MaterialIndex {index}");
            current = sphere.material;
        }
        let _ = writeln!(
            text,
            "    Sphere {{ center {} radius {} }}",
            v(sphere.center_world),
            sphere.radius_world
        );
    }
    text.push_str("}\n");
    text
}
