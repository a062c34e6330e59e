//! The viewer's side and bottom panels, each a `*_ui` function over plain state: the view
//! controls, the quality, file and export sections, and the status bar. No rendering math lives
//! here. (The images are in [`super::images`], the depth tools in [`super::depth_tools`].)

use egui::{RichText, Ui};

use super::state::{ExportFormat, ExportSettings};
use crate::explore::SliderRanges;
use crate::export::ExtraDepth;
use crate::output::depth_file::RawDepthFormat;
use crate::render::sampling::MAX_FILTER_SIZE;
use crate::render::{Filter, MAX_SIDE_PX, Precision, Quality, Sampler, Sampling, View};

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
pub fn controls_ui(ui: &mut Ui, view: &mut View, ranges: &SliderRanges) {
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
pub fn quality_ui(ui: &mut Ui, quality: &mut Quality) {
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
pub const SAMPLE_CHOICES: [u32; 7] = [1, 4, 9, 16, 25, 64, 256];

/// What the file section asked for.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct FileRequests {
    /// Open the scene at the typed path.
    pub open_path: Option<String>,
    /// Write the scene with the current camera to the typed path.
    pub save_view: bool,
}

/// A typed scene path with an "Open path" button, and a path to save the current view as a scene
/// file to (both work without any file dialog).
pub fn file_ui(ui: &mut Ui, path_text: &mut String, save_path: &mut String) -> FileRequests {
    let mut requests = FileRequests::default();
    ui.heading("Scene file");
    ui.horizontal(|ui| {
        let label = ui.label("view to");
        ui.add(egui::TextEdit::singleline(save_path).desired_width(150.0))
            .labelled_by(label.id);
        if ui
            .button("Save view as scene")
            .on_hover_text("write the scene with the current camera (centre, direction, up, size)")
            .clicked()
        {
            requests.save_view = true;
        }
    });
    ui.horizontal(|ui| {
        let label = ui.label("path");
        let field = ui
            .add(egui::TextEdit::singleline(path_text).desired_width(170.0))
            .labelled_by(label.id);
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if ui.button("Open path").clicked() || entered {
            requests.open_path = Some(path_text.clone());
        }
    });
    requests
}

/// What the export section asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ExportRequests {
    /// Write to the typed path now.
    pub export_to_path: bool,
}

/// Export options: size, format, side by side, and the path to write to.
pub fn export_ui(
    ui: &mut Ui,
    settings: &mut ExportSettings,
    dialog_note: Option<&str>,
) -> ExportRequests {
    let mut requests = ExportRequests::default();
    ui.heading("Export");
    ui.checkbox(&mut settings.displayed_size, "displayed size");
    if !settings.displayed_size {
        ui.horizontal(|ui| {
            let label = ui.label("export size");
            ui.add(egui::DragValue::new(&mut settings.size_px[0]).range(1..=MAX_SIDE_PX))
                .labelled_by(label.id);
            ui.label("×");
            ui.add(egui::DragValue::new(&mut settings.size_px[1]).range(1..=MAX_SIDE_PX))
                .labelled_by(label.id);
        });
    }
    ui.horizontal(|ui| {
        ui.radio_value(&mut settings.format, ExportFormat::Png, "PNG");
        ui.radio_value(&mut settings.format, ExportFormat::Tga, "TGA");
    });
    ui.checkbox(&mut settings.side_by_side, "also side by side");
    ui.horizontal(|ui| {
        let label = ui.label("depth also as");
        let choices = [
            (ExtraDepth::None, "nothing more"),
            (ExtraDepth::Png16, "16-bit PNG"),
            (ExtraDepth::Raw(RawDepthFormat::Pfm), "raw t, PFM"),
            (ExtraDepth::Raw(RawDepthFormat::Exr), "raw t, EXR"),
        ];
        let selected = choices
            .iter()
            .find(|(choice, _)| *choice == settings.extra_depth)
            .map_or("nothing more", |(_, name)| name);
        egui::ComboBox::from_id_salt("extra depth")
            .selected_text(selected)
            .show_ui(ui, |ui| {
                for (choice, name) in choices {
                    ui.selectable_value(&mut settings.extra_depth, choice, name);
                }
            })
            .response
            .labelled_by(label.id);
    });
    ui.horizontal(|ui| {
        let label = ui.label("to");
        ui.add(egui::TextEdit::singleline(&mut settings.path).desired_width(150.0))
            .labelled_by(label.id);
        if ui.button("Export to path").clicked() {
            requests.export_to_path = true;
        }
    });
    ui.label(
        RichText::new(
            "writes <name>_colour, <name>_depth (in the colour map on screen), <name>_both, \
             <name>_scene.txt (the current camera) and <name>_command.sh (the command line \
             that renders the same files)",
        )
        .small()
        .weak(),
    );
    if let Some(note) = dialog_note {
        ui.label(
            RichText::new(note)
                .small()
                .color(ui.visuals().warn_fg_color),
        );
    }
    requests
}

/// What the status bar shows.
pub struct StatusLine<'a> {
    /// Render time of the frame on screen, milliseconds.
    pub render_ms: Option<f64>,
    /// Size of the frame on screen.
    pub size_px: Option<[u32; 2]>,
    /// Spheres in the scene.
    pub sphere_count: usize,
    /// The scene's path or name.
    pub scene_name: &'a str,
    /// Precision the frame on screen was rendered in.
    pub precision: Option<Precision>,
    /// What is on screen: "preview" or the refined quality.
    pub stage: Option<String>,
    /// A render is in flight.
    pub busy: bool,
    /// A scene load that has run long enough to show its progress: its name and share done.
    pub loading: Option<(String, f32)>,
    /// Message of the last action (export result, view problem), with whether it is an error.
    pub message: Option<(&'a str, bool)>,
}

/// The status bar: render time, image size, sphere count, scene path, last message.
pub fn status_bar_ui(ui: &mut Ui, status: &StatusLine<'_>) {
    ui.horizontal(|ui| {
        match status.render_ms {
            Some(ms) => ui.label(format!("render {ms:.1} ms")),
            None => ui.label("render —"),
        };
        ui.separator();
        if let Some([w, h]) = status.size_px {
            ui.label(format!("{w}×{h} px"));
            ui.separator();
        }
        if let Some(precision) = status.precision {
            ui.label(precision.name());
            ui.separator();
        }
        if let Some(stage) = &status.stage {
            ui.label(stage);
            ui.separator();
        }
        let plural = if status.sphere_count == 1 { "" } else { "s" };
        ui.label(format!("{} sphere{plural}", status.sphere_count));
        ui.separator();
        ui.label(status.scene_name);
        if status.busy {
            ui.separator();
            ui.spinner();
        }
        if let Some((name, fraction)) = &status.loading {
            ui.separator();
            ui.add(
                egui::ProgressBar::new(*fraction)
                    .desired_width(160.0)
                    .show_percentage(),
            );
            ui.label(format!("loading {name}"));
        }
        if let Some((message, is_error)) = status.message {
            ui.separator();
            let colour = if is_error {
                ui.visuals().error_fg_color
            } else {
                ui.visuals().text_color()
            };
            ui.label(RichText::new(message).color(colour));
        }
    });
}

/// A red banner with an error (e.g. a scene that failed to parse) and a dismiss button.
/// Returns true when dismissed.
pub fn error_banner_ui(ui: &mut Ui, message: &str) -> bool {
    let mut dismissed = false;
    ui.horizontal(|ui| {
        ui.label(
            RichText::new(message)
                .color(ui.visuals().error_fg_color)
                .monospace(),
        );
        if ui.button("Dismiss").clicked() {
            dismissed = true;
        }
    });
    dismissed
}
