//! The side panel's view controls (camera centre, size, depth range, direction and up) and the
//! quality section, each a `*_ui` function over plain state. No rendering math lives here.

use egui::Ui;

use crate::explore::{Reach, SIZE_REACH_FACTOR, SliderRanges, window_around};
use crate::render::sampling::settings::MAX_FILTER_SIZE;
use crate::render::{Filter, Quality, Sampler, Sampling, View};

fn widened(range: &std::ops::RangeInclusive<f64>, value: f64) -> std::ops::RangeInclusive<f64> {
    if value.is_finite() {
        range.start().min(value)..=range.end().max(value)
    } else {
        range.clone()
    }
}

/// Shift or Alt while dragging a slider moves it at this share of the speed.
pub(crate) const FINE_DRAG: f64 = 0.1;

/// A notch of the wheel on a focused slider nudges it by this share of its range (Shift: a
/// tenth of that).
const NUDGE_SHARE: f64 = 0.005;

/// The width kept for a slider's value field, points.
const VALUE_FIELD_POINTS: f32 = 90.0;

/// One slider of the view: its name and value field on a line, the slider below as wide as the
/// panel. The slider spans `reach` around the value (held from the start of a drag to its end,
/// inside `range`), so its step follows the value; Shift or Alt drag finely, the wheel nudges it
/// while it has the keyboard focus, and a typed value may lie anywhere.
fn slider(
    ui: &mut Ui,
    label: &str,
    value: &mut f64,
    (range, reach): (std::ops::RangeInclusive<f64>, Option<Reach>),
    logarithmic: bool,
    tooltip: &str,
) {
    let before = *value;
    let hint =
        format!("{tooltip}\nType a value, drag (Shift or Alt: fine), or scroll while focused");
    // The window the slider spans: held while a drag lasts, else around the value.
    let window_id = ui.make_persistent_id(("slider window", label));
    let held: Option<(f64, f64)> = ui.data(|data| data.get_temp(window_id));
    let window = match (held, reach) {
        (Some((low, high)), _) => low..=high,
        (None, Some(reach)) => window_around(&range, *value, reach),
        (None, None) => range,
    };
    let (low, high) = (*window.start(), *window.end());
    let name = ui
        .horizontal(|ui| {
            let name = ui.label(label);
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                let per_point = (high - low) / f64::from(ui.available_width().max(1.0));
                ui.add_sized(
                    [VALUE_FIELD_POINTS, ui.spacing().interact_size.y],
                    egui::DragValue::new(value)
                        .speed(per_point.max(f64::MIN_POSITIVE))
                        .max_decimals(6),
                )
                .labelled_by(name.id)
                .on_hover_text(&hint);
            });
            name
        })
        .inner;
    ui.spacing_mut().slider_width = ui.available_width().max(60.0);
    let response = ui
        .add(
            egui::Slider::new(value, window)
                .show_value(false)
                .logarithmic(logarithmic)
                .clamping(egui::SliderClamping::Never),
        )
        .labelled_by(name.id)
        .on_hover_text(&hint);
    let modifiers = ui.input(|i| i.modifiers);
    let fine = modifiers.shift || modifiers.alt;
    // A slider puts the value under the pointer; a fine drag moves it by a tenth of the pointer's
    // travel since the drag began instead (and a press does not jump).
    let start_id = response.id.with("fine drag start");
    if response.drag_started() {
        ui.data_mut(|data| {
            data.insert_temp(start_id, (before, *value));
            data.insert_temp(window_id, (low, high));
        });
    }
    let start: Option<(f64, f64)> = ui.data(|data| data.get_temp(start_id));
    if (response.dragged() || response.drag_stopped())
        && fine
        && let Some((start_value, start_raw)) = start
        && value.is_finite()
    {
        *value = start_value + (*value - start_raw) * FINE_DRAG;
    }
    if response.drag_stopped() || !response.dragged() && !response.drag_started() {
        ui.data_mut(|data| {
            data.remove::<(f64, f64)>(start_id);
            data.remove::<(f64, f64)>(window_id);
        });
    }
    if response.has_focus() {
        // Wheel notches (not the smoothed scroll, which spreads one notch over frames).
        let scroll: f32 = ui.input(|i| {
            i.raw
                .events
                .iter()
                .filter_map(|event| match event {
                    egui::Event::MouseWheel { delta, .. } => Some(delta.y),
                    _ => None,
                })
                .sum()
        });
        if scroll != 0.0 && before.is_finite() {
            let share = if fine { NUDGE_SHARE * 0.1 } else { NUDGE_SHARE };
            let notches = f64::from(scroll.signum());
            *value = if logarithmic && before > 0.0 {
                before * (1.0 + 10.0 * share).powf(notches)
            } else {
                before + notches * share * (high - low)
            };
        }
    }
}

/// What an edit of the view controls did.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Edit {
    /// A valid change was applied to the view.
    pub(crate) applied: bool,
    /// A change that would make the view unrenderable, not applied, and why.
    pub(crate) rejected: Option<String>,
}

/// Sliders (each with a typed-in value) for the camera centre, size, depth range, direction and
/// up. A change that leaves the view renderable is applied to `view`; one that does not is not
/// (the fields show the view's values again) and the returned [`Edit`] says why, so an invalid
/// value never blocks the valid edits after it.
pub(crate) fn controls_ui(ui: &mut Ui, view: &mut View, ranges: &SliderRanges) -> Edit {
    let mut candidate = *view;
    ui.heading("View");
    let axes = ["x", "y", "z"];
    for (axis, name) in ["centre x", "centre y", "centre z"].into_iter().enumerate() {
        let tooltip = format!("The camera's centre, world {}", axes[axis]);
        slider(
            ui,
            name,
            &mut candidate.center_world[axis],
            (ranges.center_world[axis].clone(), Some(ranges.center_reach)),
            false,
            &tooltip,
        );
    }
    slider(
        ui,
        "size",
        &mut candidate.size_world,
        (
            ranges.size_world.clone(),
            Some(Reach::Times(SIZE_REACH_FACTOR)),
        ),
        true,
        "The screen's width in world units: smaller zooms in",
    );
    ui.separator();
    ui.label("Depth range (t: near … far)");
    slider(
        ui,
        "depth min",
        &mut candidate.depth_range.min_t,
        (ranges.depth_t.clone(), Some(ranges.depth_reach)),
        false,
        "t drawn white (near)",
    );
    slider(
        ui,
        "depth max",
        &mut candidate.depth_range.max_t,
        (ranges.depth_t.clone(), Some(ranges.depth_reach)),
        false,
        "t drawn black (far)",
    );
    ui.separator();
    ui.collapsing("Direction and up", |ui| {
        let unit = -1.0..=1.0;
        for (axis, name) in ["direction x", "direction y", "direction z"]
            .into_iter()
            .enumerate()
        {
            let range = widened(&unit, candidate.direction_world[axis]);
            let tooltip = format!("The view direction, world {} (any length)", axes[axis]);
            slider(
                ui,
                name,
                &mut candidate.direction_world[axis],
                (range, None),
                false,
                &tooltip,
            );
        }
        for (axis, name) in ["up x", "up y", "up z"].into_iter().enumerate() {
            let range = widened(&unit, candidate.up_world[axis]);
            let tooltip = format!("Up, world {} (need not be perpendicular)", axes[axis]);
            slider(
                ui,
                name,
                &mut candidate.up_world[axis],
                (range, None),
                false,
                &tooltip,
            );
        }
    });
    if candidate == *view {
        return Edit::default();
    }
    match candidate.validate() {
        Ok(_) => {
            *view = candidate;
            Edit {
                applied: true,
                rejected: None,
            }
        }
        Err(error) => Edit {
            applied: false,
            rejected: Some(format!("not applied: {error}")),
        },
    }
}

/// The quality section: samples per pixel (and their sampler and filter).
pub(crate) fn quality_ui(ui: &mut Ui, quality: &mut Quality) {
    ui.heading("Quality");
    let mut samples = quality.sampling.map_or(1, |s| s.samples);
    ui.horizontal(|ui| {
        let label = ui.label("samples per pixel");
        egui::ComboBox::from_id_salt("samples per pixel")
            .selected_text(samples.to_string())
            .show_ui(ui, |ui| {
                for option in SAMPLE_CHOICES {
                    ui.selectable_value(&mut samples, option, option.to_string());
                }
            })
            .response
            .labelled_by(label.id)
            .on_hover_text(
                "Samples per pixel: 1 is the course's exact picture; more smooths edges",
            );
    });
    if samples == 1 {
        quality.sampling = None;
        return;
    }
    // The trade-off study's front (docs/tradeoff.md): uniform samples with a box over the pixel.
    let sampling = quality.sampling.get_or_insert(Sampling {
        sampler: Sampler::Uniform,
        samples,
        filter: Filter::PIXEL_BOX,
        seed: 0,
    });
    sampling.samples = samples;
    ui.horizontal(|ui| {
        ui.label("sampler");
        for sampler in Sampler::ALL {
            ui.radio_value(&mut sampling.sampler, sampler, sampler.name())
                .on_hover_text(match sampler {
                    Sampler::Uniform => "an n×n grid of cell centres",
                    Sampler::Jittered => "one random point in each cell of an n×n grid",
                    Sampler::Random => "independent random points",
                });
        }
    });
    ui.horizontal(|ui| {
        ui.label("filter");
        let size = sampling.filter.size();
        for filter in [
            Filter::Box { radius: size },
            Filter::Tent { radius: size },
            Filter::Gaussian { sigma: size },
        ] {
            if ui
                .radio(sampling.filter.name() == filter.name(), filter.name())
                .on_hover_text("How samples combine into a pixel; box 0.5 is the pixel's area")
                .clicked()
            {
                sampling.filter = filter;
            }
        }
        let mut size = sampling.filter.size();
        let label = ui.label("size px");
        ui.add(
            egui::DragValue::new(&mut size)
                .range(0.1..=MAX_FILTER_SIZE)
                .speed(0.05),
        )
        .labelled_by(label.id)
        .on_hover_text("The filter's radius (sigma for Gaussian), pixels");
        sampling.filter = with_size(sampling.filter, size);
    });
}

/// Samples-per-pixel choices offered (squares, so every sampler accepts them).
pub(crate) const SAMPLE_CHOICES: [u32; 7] = [1, 4, 9, 16, 25, 64, 256];

/// The same kind of filter as `filter` with another size, pixels.
fn with_size(filter: Filter, size: f32) -> Filter {
    match filter {
        Filter::Box { .. } => Filter::Box { radius: size },
        Filter::Tent { .. } => Filter::Tent { radius: size },
        Filter::Gaussian { .. } => Filter::Gaussian { sigma: size },
    }
}
