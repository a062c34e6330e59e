//! The side panel's view controls (camera centre, size, depth range, direction and up) and the
//! quality section, each a `*_ui` function over plain state. No rendering math lives here.

use egui::Ui;

use crate::explore::SliderRanges;
use crate::render::sampling::MAX_FILTER_SIZE;
use crate::render::{Filter, Precision, Quality, Sampler, Sampling, View};

fn widened(range: &std::ops::RangeInclusive<f64>, value: f64) -> std::ops::RangeInclusive<f64> {
    if value.is_finite() {
        range.start().min(value)..=range.end().max(value)
    } else {
        range.clone()
    }
}

fn slider(ui: &mut Ui, label: &str, value: &mut f64, range: std::ops::RangeInclusive<f64>) {
    ui.add(
        egui::Slider::new(value, range)
            .text(label)
            .clamping(egui::SliderClamping::Never)
            .max_decimals(6),
    );
}

/// Sliders (each with a typed-in value) for the camera centre, size, depth range, direction and
/// up. Edits `view` in place. ("Reset view" is in the toolbar.)
pub(crate) fn controls_ui(ui: &mut Ui, view: &mut View, ranges: &SliderRanges) {
    ui.heading("View");
    for (axis, name) in ["centre x", "centre y", "centre z"].into_iter().enumerate() {
        let mut value = view.center_world[axis];
        slider(ui, name, &mut value, ranges.center_world[axis].clone());
        view.center_world[axis] = value;
    }
    ui.add(
        egui::Slider::new(&mut view.size_world, ranges.size_world.clone())
            .text("size")
            .logarithmic(true)
            .clamping(egui::SliderClamping::Never)
            .max_decimals(6),
    );
    ui.separator();
    ui.label("Depth range (t: near … far)");
    slider(
        ui,
        "depth min",
        &mut view.depth_range.min_t,
        ranges.depth_t.clone(),
    );
    slider(
        ui,
        "depth max",
        &mut view.depth_range.max_t,
        ranges.depth_t.clone(),
    );
    ui.separator();
    ui.collapsing("Direction and up", |ui| {
        let unit = -1.0..=1.0;
        for (axis, name) in ["direction x", "direction y", "direction z"]
            .into_iter()
            .enumerate()
        {
            let mut value = view.direction_world[axis];
            let range = widened(&unit, value);
            slider(ui, name, &mut value, range);
            view.direction_world[axis] = value;
        }
        for (axis, name) in ["up x", "up y", "up z"].into_iter().enumerate() {
            let mut value = view.up_world[axis];
            let range = widened(&unit, value);
            slider(ui, name, &mut value, range);
            view.up_world[axis] = value;
        }
    });
}

/// The quality section: precision mode.
pub(crate) fn quality_ui(ui: &mut Ui, quality: &mut Quality) {
    ui.heading("Quality");
    ui.horizontal(|ui| {
        ui.label("precision");
        for precision in Precision::ALL {
            ui.radio_value(&mut quality.precision, precision, precision.name())
                .on_hover_text(match precision {
                    Precision::F64 => "64-bit: exact at every extreme",
                    Precision::F32 => {
                        "32-bit arithmetic; exact coverage, depth exact only inside its safe range"
                    }
                    Precision::Auto => "f32 where it is safe for the frame, else f64",
                });
        }
    });
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
            .labelled_by(label.id);
    });
    if samples == 1 {
        quality.sampling = None;
        return;
    }
    let sampling = quality.sampling.get_or_insert(Sampling {
        sampler: Sampler::Jittered,
        samples,
        filter: Filter::Tent { radius: 1.0 },
        seed: 0,
    });
    sampling.samples = samples;
    ui.horizontal(|ui| {
        ui.label("sampler");
        for sampler in Sampler::ALL {
            ui.radio_value(&mut sampling.sampler, sampler, sampler.name());
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
        .labelled_by(label.id);
        sampling.filter = sampling.filter.with_size(size);
    });
}

/// Samples-per-pixel choices offered (squares, so every sampler accepts them).
pub(crate) const SAMPLE_CHOICES: [u32; 7] = [1, 4, 9, 16, 25, 64, 256];
