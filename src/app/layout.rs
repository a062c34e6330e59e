//! Composing the window: the toolbar, the status bar, the controls (a side panel in wide windows,
//! a drawer over the images in narrow ones, always reachable from the toolbar's "Controls"), the
//! central area with the images, and the windows above it (the replace confirmation, the
//! shortcuts overlay, a scene's error). Nothing here moves the layout when a message comes or
//! goes: errors float over the images, the status line keeps one line.

use std::path::PathBuf;

use super::actions::{Action, Write};
use super::compare::{CompareShow, CompareSource, CompareState, ComparisonPixels};
use super::confirm;
use super::probe::Probe;
use super::render_requests::Frames;
use super::scene_loading::OpenScene;
use super::settings::Settings;
use super::status::Status;
use super::ui::histogram::HistogramStyle;
use super::ui::images::{Compared, Footer, ShownImages, images_ui};
use super::ui::status_bar::{StatusLine, error_overlay_ui, status_bar_ui};
use super::ui::{
    depth_section, file_sections, help, probe_text, toolbar, view_controls, views_section,
};
use super::viewing::Viewing;
use super::writes::Writes;
use crate::export::numbers::grouped;
use crate::render::View;
use egui::TextureHandle;

/// What the side panel's fields hold between frames.
#[derive(Debug, Clone, Default)]
pub(crate) struct Fields {
    /// The typed scene path of the file section.
    pub(crate) path_text: String,
    /// The name typed for a new named view.
    pub(crate) view_name: String,
    /// A view edit that was not applied, and why.
    pub(crate) invalid_edit: Option<String>,
}

/// The viewer's panels: the side panel's fields, whether the drawer of narrow windows and the
/// shortcuts overlay are open.
#[derive(Debug, Clone, Default)]
pub(crate) struct Panels {
    /// The side panel's typed fields.
    pub(crate) fields: Fields,
    /// The shortcuts and gestures overlay is open.
    pub(crate) help_open: bool,
    /// The controls drawer of narrow windows is open.
    pub(crate) drawer_open: bool,
    /// The pixel trace window's text, while it is open.
    pub(crate) trace: Option<String>,
}

/// Below this window width the controls are closed at first and the toolbar's Controls opens
/// them: beside the images from [`PUSH_ASIDE_FROM_POINTS`], as a drawer over them below that.
pub(crate) const DRAWER_BELOW_POINTS: f32 = 900.0;

/// How far below the toolbar a scene's error floats: past the images' captions (the depth
/// image's names its range), over the images.
const ERROR_BELOW_TOOLBAR_POINTS: f32 = 36.0;

/// Width of the side panel (or the drawer) in the narrowest windows, points.
const PANEL_POINTS: f32 = 320.0;

/// The side panel's width, points: a quarter of the window (so that sliders grow with it), from
/// [`PANEL_POINTS`] to 440.
pub(crate) fn panel_points(window_width: f32) -> f32 {
    (0.25 * window_width).clamp(PANEL_POINTS, 440.0)
}

/// From this window width up to [`DRAWER_BELOW_POINTS`] the opened controls push the images aside
/// (they shrink, nothing is covered); below it they are a drawer over the images.
pub(crate) const PUSH_ASIDE_FROM_POINTS: f32 = 640.0;

/// The window's parts for one frame's drawing, borrowed from the coordinator: the state of each
/// feature the panels show and edit. What the user asks for comes back as actions.
pub(super) struct Window<'a> {
    pub(super) settings: &'a mut Settings,
    pub(super) scene: &'a mut OpenScene,
    pub(super) viewing: &'a mut Viewing,
    pub(super) frames: &'a Frames,
    pub(super) writes: &'a mut Writes,
    pub(super) panels: &'a mut Panels,
    pub(super) compare: &'a mut CompareState,
    pub(super) status: Option<&'a Status>,
}

/// A render, a write or a comparison is under way.
pub(super) fn busy(frames: &Frames, writes: &Writes, compare: &CompareState) -> bool {
    frames.worker.as_ref().is_some_and(|w| !w.is_idle()) || writes.task.is_some() || compare.busy()
}

impl Window<'_> {
    /// The whole window; returns what the user asked for.
    pub(super) fn ui(mut self, ui: &mut egui::Ui) -> Vec<Action> {
        let mut actions = Vec::new();
        let window_width = ui.available_width();
        let narrow = window_width < DRAWER_BELOW_POINTS;
        let toolbar = egui::Panel::top("toolbar").show(ui, |ui| {
            // In a narrow window the toggle opens the drawer (closed at first, so the images show).
            let controls = if narrow {
                &mut self.panels.drawer_open
            } else {
                &mut self.settings.show_controls
            };
            let state = toolbar::ToolbarState {
                show_controls: controls,
                can_undo: self.viewing.history.can_undo(&self.viewing.view),
                can_redo: self.viewing.history.can_redo(),
                narrow: window_width < toolbar::MENU_BELOW_POINTS,
            };
            actions.extend(toolbar::toolbar_ui(ui, state));
        });
        // The drawer opens just below the toolbar, however many rows the toolbar wraps into.
        let toolbar_bottom = toolbar.response.rect.bottom();
        egui::Panel::bottom("status").show(ui, |ui| status_bar_ui(ui, &self.status_line()));
        if self.settings.show_controls && !narrow {
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(panel_points(window_width))
                .max_size((0.45 * window_width).max(200.0))
                .show(ui, |ui| actions.extend(self.side_panel_ui(ui)));
        }
        // In a narrow window that still has room, the opened controls push the images aside.
        let push_aside = narrow && window_width >= PUSH_ASIDE_FROM_POINTS;
        if self.panels.drawer_open && push_aside {
            egui::Panel::left("controls, narrow")
                .resizable(false)
                .exact_size(PANEL_POINTS - 40.0)
                .show(ui, |ui| actions.extend(self.side_panel_ui(ui)));
        }
        egui::CentralPanel::default().show(ui, |ui| actions.extend(self.images_ui(ui)));
        let ctx = ui.ctx().clone();
        if self.panels.drawer_open && narrow && !push_aside {
            let mut open = true;
            // As tall as the window allows, whatever height it had before the window changed.
            let height = (ctx.content_rect().height() - toolbar_bottom - 64.0).max(100.0);
            let width = PANEL_POINTS.min(window_width - 16.0);
            egui::Window::new("View controls")
                .open(&mut open)
                .anchor(
                    egui::Align2::LEFT_TOP,
                    egui::vec2(4.0, toolbar_bottom + 4.0),
                )
                .fixed_size(egui::vec2(width, height))
                .collapsible(false)
                .resizable(false)
                .show(&ctx, |ui| actions.extend(self.side_panel_ui(ui)));
            self.panels.drawer_open = open;
        }
        if let Some(error) = self.scene.error.clone()
            && error_overlay_ui(&ctx, &error, toolbar_bottom + ERROR_BELOW_TOOLBAR_POINTS)
        {
            self.scene.error = None;
        }
        actions.extend(self.confirm_ui(&ctx));
        super::pixel_trace::trace_ui(&ctx, &mut self.panels.trace);
        if self.panels.help_open {
            self.panels.help_open = help::help_ui(&ctx);
        }
        actions
    }

    /// The controls: view, depth tools, quality, named views, file and export sections.
    fn side_panel_ui(&mut self, ui: &mut egui::Ui) -> Vec<Action> {
        let mut actions = Vec::new();
        egui::ScrollArea::vertical().show(ui, |ui| {
            let ranges = self.scene.loaded.ranges(&self.viewing.view);
            let edit = view_controls::controls_ui(ui, &mut self.viewing.view, &ranges);
            if let Some(problem) = edit.rejected {
                self.panels.fields.invalid_edit = Some(problem);
            } else if edit.applied {
                self.panels.fields.invalid_edit = None;
            }
            if let Some(problem) = &self.panels.fields.invalid_edit {
                ui.colored_label(ui.visuals().error_fg_color, problem);
            }
            actions.extend(depth_section::depth_tools_ui(ui, &mut self.settings.depth));
            ui.separator();
            view_controls::quality_ui(ui, &mut self.settings.quality);
            ui.separator();
            actions.extend(super::ui::compare_section::compare_ui(
                ui,
                self.compare,
                &self.settings.quality,
            ));
            ui.separator();
            let named = self
                .scene
                .loaded
                .path
                .as_ref()
                .map(|path| super::saved_views::SceneViews::key(path))
                .and_then(|key| self.settings.views.named.get(&key));
            let has_file = self.scene.loaded.path.is_some();
            actions.extend(views_section::views_ui(
                ui,
                named.map_or(&[], Vec::as_slice),
                &mut self.panels.fields.view_name,
                has_file,
            ));
            ui.separator();
            let export = &mut self.settings.export;
            let file = file_sections::file_ui(
                ui,
                &mut self.panels.fields.path_text,
                &mut export.scene_path,
            );
            if let Some(path) = file.open_path {
                actions.push(Action::Open(PathBuf::from(path.trim())));
            }
            if let Some(index) = file.open_bundled {
                actions.push(Action::OpenBundled(index));
            }
            if file.save_view {
                let path = PathBuf::from(export.scene_path.trim());
                actions.push(Action::Write(Write::SaveViewTo(path)));
            }
            ui.separator();
            let requests = file_sections::export_ui(ui, export, self.writes.dialog_note);
            if requests.export_to_path {
                let base = PathBuf::from(export.path.trim());
                actions.push(Action::Write(Write::ExportTo(base)));
            }
            if requests.course_files {
                actions.push(Action::Write(Write::CourseFiles));
            }
        });
        actions
    }

    /// The modal asking whether to replace files (or to make the folder first): the user's yes.
    fn confirm_ui(&mut self, ctx: &egui::Context) -> Option<Action> {
        confirm::answer(&mut self.writes.pending_replace, ctx).map(Action::Confirmed)
    }

    /// What the status bar shows now.
    fn status_line(&self) -> StatusLine<'_> {
        let shown = self.frames.shown.as_ref();
        StatusLine {
            render_ms: shown.map(|s| s.render_ms),
            size_px: self.frames.size_px(),
            stage: shown.map(|s| {
                if self.frames.shows_preview_of(&self.settings.quality) {
                    "preview (1 sample)".to_owned()
                } else {
                    s.quality.describe()
                }
            }),
            magnification: self.viewing.magnifier.zoom,
            sphere_count: self.scene.loaded.scene.spheres.len(),
            scene_name: self.scene.loaded.name(),
            busy: busy(self.frames, self.writes, self.compare),
            loading: self
                .scene
                .loading
                .as_ref()
                .filter(|pending| pending.shows_progress())
                .map(|pending| (pending.path.display().to_string(), pending.fraction())),
            message: self.status.filter(|status| !status.is_stale()),
        }
    }

    /// The probe of the frame on screen at image position `px` (pixels, y up).
    fn probe_at(&self, px: glam::DVec2) -> Option<Probe> {
        self.frames
            .probe_at(&self.scene.loaded.scene, self.scene.epoch, px)
    }

    /// The two images with the probe and the histogram; returns the gestures made on them.
    fn images_ui(&mut self, ui: &mut egui::Ui) -> Vec<Action> {
        let style = super::render_requests::depth_style(&self.settings.depth);
        let range = self.frames.shown.as_ref().map(|s| s.view.depth_range);
        let depth_rgb = |probe: &crate::app::probe::Probe| match (range, probe.hit) {
            (Some(range), Some(hit)) => style.colour_map.rgb(&range, hit.t, style.no_hit_rgb),
            _ => style.no_hit_rgb,
        };
        let pinned_px = self.viewing.pinned_px(self.frames.shown.as_ref());
        let pinned = pinned_px.and_then(|px| self.probe_at(px));
        let hover = self.viewing.probe.hover_px.and_then(|px| self.probe_at(px));
        let mut probe_lines = probe_text::probe_lines(pinned, hover, depth_rgb);
        if let Some(px) = self.viewing.probe.hover_px {
            probe_lines.extend(self.compare.probe_lines(px));
        }
        self.close_stale_measurement();
        let compared = compared_picture(self.compare, &self.viewing.view);
        let shown = self.frames.shown.as_ref().map(|s| ShownImages {
            colour: &s.colour,
            depth: &s.depth,
            size_px: [s.frame.width_px, s.frame.height_px],
            depth_range: s.view.depth_range,
            histogram: s.histogram.as_ref(),
            compared,
        });
        let footer = Footer {
            probe_lines: &probe_lines,
            pinned: pinned_px,
            has_pin: self.viewing.probe.pinned_world.is_some(),
            hover: self.viewing.probe.hover_px,
            depth_range: &mut self.viewing.view.depth_range,
            histogram_style: HistogramStyle {
                log_counts: self.settings.depth.log_counts,
                height: 0.0,
            },
            colour_map: style.colour_map,
            no_hit_rgb: style.no_hit_rgb,
            magnifier: self.viewing.magnifier,
        };
        let gestures = images_ui(ui, shown.as_ref(), footer);
        // While their image is compared the view keeps its size, so the two line up.
        let (width_px, height_px) = self.compare.held_size_px().unwrap_or(gestures.wanted_px);
        self.viewing.view.width_px = width_px;
        self.viewing.view.height_px = height_px;
        super::input::gesture_actions(&gestures)
    }

    /// A measurement of the chosen quality is of one view: it closes when the view changes.
    fn close_stale_measurement(&mut self) {
        if let Some(current) = &self.compare.current
            && let CompareSource::Quality(_) = current.pixels.source
        {
            let mut measured = current.pixels.view;
            measured.depth_range = self.viewing.view.depth_range;
            if measured != self.viewing.view {
                self.compare.close();
            }
        }
    }
}

/// What the Compare section shows in place of the rendered images: one picture, or one for each
/// image of a pair.
fn compared_picture<'a>(compare: &'a CompareState, view: &View) -> Vec<Compared<'a>> {
    let Some(current) = compare.current.as_ref() else {
        return Vec::new();
    };
    let pixels = &current.pixels;
    let theirs = match pixels.source {
        CompareSource::File(_) => "theirs",
        CompareSource::Quality(_) => "chosen quality",
    };
    let moved = match pixels.source {
        CompareSource::File(_) => {
            let mut compared = pixels.view;
            compared.depth_range = view.depth_range;
            compared != *view
        }
        CompareSource::Quality(_) => false,
    };
    let note = if moved {
        "  (view moved: Home lines it up again)"
    } else {
        ""
    };
    let shown: Vec<&crate::compare::Deviation> =
        pixels.statements.iter().chain(&pixels.partial).collect();
    let together = if pixels.paired.is_some() {
        ", judged together"
    } else {
        ""
    };
    let picture = |image: &'a ComparisonPixels,
                   (theirs_texture, heat_texture): (&'a TextureHandle, &'a TextureHandle),
                   highlighted: Option<(&'a TextureHandle, usize, usize)>| {
        let kind = image.kind.word();
        let (texture, caption, heat_scale) = match (highlighted, compare.show) {
            (Some((texture, index, count)), _) => (
                texture,
                format!(
                    "{kind}: the {} pixels {} explains, in colour",
                    grouped(count as f64, 0),
                    shown
                        .get(index)
                        .map_or_else(String::new, |s| s.name_and_values())
                ),
                true,
            ),
            (None, CompareShow::Rendered) => return None,
            (None, CompareShow::Theirs) => (
                theirs_texture,
                format!("{kind}: {theirs}{together} (B: the render){note}"),
                false,
            ),
            (None, CompareShow::Difference) => (
                heat_texture,
                format!(
                    "{kind}: difference, {} pixels, largest {}{together} (Shift+B: the \
                     render){note}",
                    grouped(image.difference.pixels_differing() as f64, 0),
                    image.difference.max_difference()
                ),
                true,
            ),
        };
        let (width, height) = image.theirs.dimensions();
        Some(Compared {
            index: image.kind.index(),
            texture,
            size_px: [width, height],
            caption,
            heat_scale,
        })
    };
    let mut pictures: Vec<Compared<'a>> = picture(
        pixels,
        (&current.theirs_texture, &current.heat_texture),
        compare.highlighted(false),
    )
    .into_iter()
    .collect();
    if let (Some(paired), Some((theirs, heat))) = (&pixels.paired, &current.paired_textures) {
        pictures.extend(picture(paired, (theirs, heat), compare.highlighted(true)));
    }
    pictures
}
