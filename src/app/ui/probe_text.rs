//! The probe's text: the lines describing what a pixel's ray hits (numbers as
//! [`crate::export::numbers`] writes them).

use crate::app::probe::Probe;
use crate::export::numbers::short_number;

/// Three lines describing a probe: where the pixel is, what its ray hits, and where.
pub(crate) fn describe_probe(name: &str, probe: &Probe, depth_rgb: [u8; 3]) -> Vec<String> {
    let short = short_number;
    let rgb = |[r, g, b]: [u8; 3]| format!("{r} {g} {b} #{r:02x}{g:02x}{b:02x}");
    let mut lines = vec![
        format!(
            "{name:<6} pixel ({}, {}) · screen ({}, {})",
            probe.x_px,
            probe.y_up_px,
            short(probe.screen_world.x),
            short(probe.screen_world.y)
        ),
        format!(
            "       colour {} · depth {}",
            rgb(probe.colour_rgb),
            rgb(depth_rgb)
        ),
    ];
    match &probe.hit {
        None => lines.push("       no hit".to_owned()),
        Some(hit) => {
            let material = match hit.material_index {
                Some(index) => format!(
                    "material #{index} ({}, {}, {})",
                    short(f64::from(hit.diffuse_colour.x)),
                    short(f64::from(hit.diffuse_colour.y)),
                    short(f64::from(hit.diffuse_colour.z))
                ),
                None => "default material (white)".to_owned(),
            };
            lines.push(format!(
                "       t {} · sphere #{} · {material}",
                short(hit.t),
                hit.sphere_index
            ));
            lines.push(format!(
                "       hit at world ({}, {}, {})",
                short(hit.point_world.x),
                short(hit.point_world.y),
                short(hit.point_world.z)
            ));
        }
    }
    lines
}

/// The probe's lines: the pinned pixel first, then the hovered one; `depth_rgb` gives a probed
/// pixel's colour in the depth image on screen.
pub(crate) fn probe_lines(
    pinned: Option<Probe>,
    hover: Option<Probe>,
    depth_rgb: impl Fn(&Probe) -> [u8; 3],
) -> Vec<String> {
    [("pinned", pinned), ("hover", hover)]
        .into_iter()
        .filter_map(|(name, probe)| {
            probe.map(|probe| describe_probe(name, &probe, depth_rgb(&probe)))
        })
        .flatten()
        .collect()
}
