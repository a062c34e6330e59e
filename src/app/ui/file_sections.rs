//! The side panel's file sections: opening a typed path, saving the view as a scene, and the
//! export options (all usable without a file dialog).

use egui::{RichText, Ui};

use crate::app::settings::{ExportFormat, ExportSettings};
use crate::export::ExtraDepth;
use crate::output::depth_file::RawDepthFormat;
use crate::render::MAX_SIDE_PX;
use crate::scene::bundled::BUNDLED_SCENES;

/// What the file section asked for.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub(crate) struct FileRequests {
    /// Open the scene at the typed path.
    pub(crate) open_path: Option<String>,
    /// Write the scene with the current camera to the typed path.
    pub(crate) save_view: bool,
    /// Open the bundled scene of this index ([`BUNDLED_SCENES`]).
    pub(crate) open_bundled: Option<usize>,
}

/// The menu of the scenes bundled with the program.
pub(crate) const BUNDLED_MENU: &str = "Course scenes";

/// A typed scene path with an "Open path" button, and a path to save the current view as a scene
/// file to (both work without any file dialog).
pub(crate) fn file_ui(ui: &mut Ui, path_text: &mut String, save_path: &mut String) -> FileRequests {
    let mut requests = FileRequests::default();
    ui.heading("Scene file");
    ui.horizontal(|ui| {
        let label = ui.label("view to");
        ui.add(egui::TextEdit::singleline(save_path).desired_width(150.0))
            .labelled_by(label.id)
            .on_hover_text("the scene file \"Save view as scene\" writes (asks before replacing)");
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
            .labelled_by(label.id)
            .on_hover_text("a scene file to open (Enter opens it)");
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if ui.button("Open path").clicked() || entered {
            requests.open_path = Some(path_text.clone());
        }
    });
    ui.menu_button(BUNDLED_MENU, |ui| {
        for (index, (name, _)) in BUNDLED_SCENES.iter().enumerate() {
            if ui.button(*name).clicked() {
                requests.open_bundled = Some(index);
                ui.close();
            }
        }
    })
    .response
    .on_hover_text("the course's scenes and the showcase scenes, bundled with the program");
    requests
}

/// What the export section asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct ExportRequests {
    /// Write to the typed path now.
    pub(crate) export_to_path: bool,
    /// Write the course's files into the typed path's folder.
    pub(crate) course_files: bool,
}

/// The button that writes the course's files.
pub(crate) const COURSE_FILES: &str = "Course files";

/// Export options: size, format, side by side, and the path to write to.
pub(crate) fn export_ui(
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
        ui.radio_value(&mut settings.format, ExportFormat::Png, "PNG")
            .on_hover_text("image format when the path names none (a .png or .tga path decides)");
        ui.radio_value(&mut settings.format, ExportFormat::Tga, "TGA")
            .on_hover_text("uncompressed 24-bit TGA, as the course writes");
    });
    ui.horizontal(|ui| {
        ui.checkbox(&mut settings.side_by_side, "also side by side")
            .on_hover_text("colour and depth in one picture");
        ui.add_enabled(
            settings.side_by_side,
            egui::Checkbox::new(&mut settings.legend, "with a legend"),
        )
        .on_hover_text(
            "a strip under the side-by-side picture: the colour bar and the depth range",
        );
    });
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
        let field = ui
            .add(egui::TextEdit::singleline(&mut settings.path).desired_width(150.0))
            .labelled_by(label.id)
            .on_hover_text("base path: name_colour, name_depth, …; a folder exports into it");
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if ui.button("Export to path").clicked() || entered {
            requests.export_to_path = true;
        }
    });
    // The format follows the path's extension, and the radio buttons show it.
    let extension = std::path::Path::new(settings.path.trim())
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("png") => settings.format = ExportFormat::Png,
        Some("tga") => settings.format = ExportFormat::Tga,
        _ => {}
    }
    super::hint::hint(
        ui,
        "writes <name>_colour, <name>_depth (in the colour map on screen), <name>_both, \
         <name>_scene.txt (the current camera) and <name>_command.sh (the command line \
         that renders the same files); asks before replacing any file",
    );
    if ui
        .button(COURSE_FILES)
        .on_hover_text(
            "what the course's command line writes for the scene file, into the path's folder: \
             outputN_MM.tga and depthN_MM.tga at 200×200 over the depth range in use, and \
             commandN_MM.sh with that command line",
        )
        .clicked()
    {
        requests.course_files = true;
    }
    if let Some(note) = dialog_note {
        ui.label(
            RichText::new(note)
                .size(super::hint::HINT_POINTS)
                .color(ui.visuals().warn_fg_color),
        );
    }
    requests
}
