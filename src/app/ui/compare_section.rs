//! The side panel's Compare section: open an image (colour or depth) to put beside the exact
//! render, choose what the compared image shows (render, theirs, difference), read the counts and
//! the diagnosis; or measure the chosen quality against the exact render.

use egui::{RichText, Ui};

use crate::app::actions::Action;
use crate::app::compare::{
    CompareShow, CompareSource, CompareState, ComparisonPixels, ImageKind, OFF_LEVELS,
    REFERENCE_SAMPLES, RangeSource,
};
use crate::app::dialogs::DialogKind;
use crate::compare::deviation::Deviation;
use crate::render::Quality;

/// The button that sets the depth range to the one read back from their depth image.
pub(crate) const USE_THEIR_RANGE: &str = "use it";

/// The accessible label of the typed image path (tests find the field by it).
pub(crate) const IMAGE_PATH_LABEL: &str = "image";

/// The section. `quality` is the chosen quality ("against the exact render" is offered when it is
/// not the exact one). Returns the actions asked for.
pub(crate) fn compare_ui(ui: &mut Ui, state: &mut CompareState, quality: &Quality) -> Vec<Action> {
    let mut actions = Vec::new();
    ui.heading("Compare");
    let before = state.kind;
    ui.horizontal(|ui| {
        ui.radio_value(&mut state.kind, ImageKind::Colour, "colour")
            .on_hover_text(
                "the image is a colour image (-output); a grey image is taken for a depth image \
                 unless this is clicked",
            );
        ui.radio_value(&mut state.kind, ImageKind::Depth, "depth")
            .on_hover_text(
                "the image is a depth image (-depth): judged under the range read from it; an \
                 image with colours is taken for a colour image unless this is clicked",
            );
    });
    // A click decides the kind, and judges the image on screen again as it.
    state.kind_forced |= state.kind != before;
    ui.horizontal(|ui| {
        let label = ui.label(IMAGE_PATH_LABEL);
        let field = ui
            .add(egui::TextEdit::singleline(&mut state.path_text).desired_width(130.0))
            .labelled_by(label.id)
            .on_hover_text(
                "their TGA or PNG image, rendered with the scene's camera (Enter opens it)",
            );
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        let typed = state.path_text.trim();
        if (ui.button("Compare image").clicked() || entered) && !typed.is_empty() {
            actions.push(Action::CompareImage(typed.into(), state.kind));
        }
        if ui
            .small_button("…")
            .on_hover_text("choose the image in a file dialog")
            .clicked()
        {
            actions.push(Action::OpenDialog(DialogKind::CompareImage(state.kind)));
        }
    });
    let exact = *quality == Quality::default();
    if ui
        .add_enabled(!exact, egui::Button::new("Against the exact render"))
        .on_hover_text(format!(
            "the current view at the chosen quality against the exact render (and, anti-aliased, \
             against {REFERENCE_SAMPLES} samples): mean error, pixels off by more than \
             {OFF_LEVELS} levels, frame time"
        ))
        .on_disabled_hover_text(
            "choose more samples per pixel first: one sample is the exact render",
        )
        .clicked()
    {
        actions.push(Action::CompareQuality);
    }
    if state.busy() {
        ui.horizontal(|ui| {
            ui.spinner();
            ui.label("comparing…");
        });
    }
    // The gallery's pictures of the statements shown, decoded before the answer is borrowed.
    let pictures: Vec<Option<egui::TextureHandle>> = match &state.current {
        Some(current) => {
            let shown: Vec<Deviation> = current
                .pixels
                .statements
                .iter()
                .chain(&current.pixels.partial)
                .cloned()
                .collect();
            shown
                .iter()
                .map(|deviation| state.gallery.picture(ui.ctx(), deviation))
                .collect()
        }
        None => Vec::new(),
    };
    let mut pointed = None;
    let Some(current) = &state.current else {
        super::hint::hint(
            ui,
            "their image is compared with the exact render of the scene's own camera at its \
             size: the view is held there while it is open",
        );
        return actions;
    };
    let pixels = &current.pixels;
    let theirs_name = match &pixels.source {
        CompareSource::File(_) => "theirs",
        CompareSource::Quality(_) => "chosen quality",
    };
    let mut show = state.show;
    ui.horizontal(|ui| {
        ui.label("show");
        ui.selectable_value(&mut show, CompareShow::Rendered, "render")
            .on_hover_text("the live render");
        ui.selectable_value(&mut show, CompareShow::Theirs, theirs_name)
            .on_hover_text("B flips between the render and this");
        ui.selectable_value(&mut show, CompareShow::Difference, "difference")
            .on_hover_text("the heat map of the difference (Shift+B)");
    });
    if show != state.show {
        actions.push(Action::CompareShow(show));
    }
    let kind = match pixels.kind {
        ImageKind::Colour => "colour",
        ImageKind::Depth => "depth",
    };
    let (width, height) = pixels.theirs.dimensions();
    match &pixels.source {
        CompareSource::File(path) => {
            ui.label(format!(
                "{kind} image {} ({width}×{height})",
                path.display()
            ));
            if let Some(assumed) = &pixels.kind_assumed {
                let other = match pixels.kind {
                    ImageKind::Colour => "depth",
                    ImageKind::Depth => "colour",
                };
                ui.label(format!(
                    "{assumed}; click {other} above to judge it as a {other} image"
                ));
            }
        }
        CompareSource::Quality(figures) => {
            ui.label(format!(
                "{} against the exact render ({width}×{height})",
                figures.quality
            ));
        }
    }
    let paired = pixels.paired.is_some();
    if let Some(other) = &pixels.paired {
        ui.label(format!(
            "judged together with the {} image {}, as the grader does",
            other.kind.word(),
            other.name()
        ))
        .on_hover_text(
            "an image of the other kind at the same size, given while one is open (or both \
             dropped at once), is judged with it; Close comparison, then give one, to judge it \
             alone",
        );
    }
    // Colour first, then depth, as the two images stand.
    let mut images: Vec<&ComparisonPixels> = pixels.images().collect();
    images.sort_by_key(|image| image.kind.index());
    for image in &images {
        let differing = image.difference.pixels_differing();
        let total = image.difference.per_pixel.len().max(1);
        let named = if paired {
            format!("{}: ", image.kind.word())
        } else {
            String::new()
        };
        ui.label(format!(
            "{named}pixels differing: {differing} ({:.2}%) · largest difference: {} levels",
            100.0 * differing as f64 / total as f64,
            image.difference.max_difference()
        ));
    }
    match &pixels.source {
        CompareSource::File(_) => {
            let matches = pixels.images().all(ComparisonPixels::matches);
            ui.label(if matches {
                "match: yes (the course's rule)".to_owned()
            } else if paired {
                let each: Vec<String> = images
                    .iter()
                    .map(|image| {
                        let word = if image.matches() {
                            "matches"
                        } else {
                            "differs"
                        };
                        format!("{} {word}", image.kind.word())
                    })
                    .collect();
                format!("match: no ({})", each.join(", "))
            } else {
                "match: no".to_owned()
            });
            if pixels.images().any(|image| image.kind == ImageKind::Depth) {
                let used = pixels.view.depth_range;
                let from = match pixels.range_source {
                    RangeSource::ReadBack => "read from their image",
                    RangeSource::Viewer => "the depth range above",
                    RangeSource::Unreadable => {
                        "the depth range above: no range can be read from their image"
                    }
                };
                ui.label(format!(
                    "judged under {} … {} ({from})",
                    used.min_t, used.max_t
                ))
                .on_hover_text(
                    "a depth image is judged under the range read from it; set the depth \
                         range above to judge it under another",
                );
            }
            if let Some(range) = pixels.depth_range_inferred
                && range != pixels.view.depth_range
            {
                ui.horizontal_wrapped(|ui| {
                    ui.label(format!(
                        "their range looks like {} … {}:",
                        range.min_t, range.max_t
                    ));
                    if ui
                        .button(USE_THEIR_RANGE)
                        .on_hover_text(
                            "read back from their image: set the depth range to it and compare \
                             again",
                        )
                        .clicked()
                    {
                        actions.push(Action::UseDepthRange(range));
                    }
                });
            }
            let diagnosis = if pixels.statements.is_empty() {
                if matches {
                    "none needed".to_owned()
                } else if let Some(because) = &pixels.not_fitted_because {
                    format!("none (no model fitted: {because})")
                } else if !pixels.alternatives.is_empty() {
                    "none (several explanations fit equally)".to_owned()
                } else if !pixels.partial.is_empty() {
                    let words: Vec<String> = pixels
                        .partial
                        .iter()
                        .map(Deviation::name_and_values)
                        .collect();
                    format!("in part: {}", words.join(", "))
                } else {
                    "none (no model of a ray caster explains it)".to_owned()
                }
            } else {
                pixels.diagnosis().join(", ")
            };
            ui.label(RichText::new(format!("diagnosis: {diagnosis}")).strong());
            if !pixels.alternatives.is_empty() {
                ui.label(format!("or: {}", pixels.alternatives.join(" | ")));
            }
            if let Some(tell_apart) = &pixels.tell_apart {
                ui.label(tell_apart);
            }
            // Each statement with what it means and what to check in their code; pointed at,
            // its gallery picture, and its pixels highlighted in the difference.
            for (index, deviation) in pixels.statements.iter().chain(&pixels.partial).enumerate() {
                let response = ui
                    .label(RichText::new(format!(
                        "{}: {}",
                        deviation.name_and_values(),
                        deviation.explanation()
                    )))
                    .on_hover_ui(|ui| statement_tip(ui, deviation, pictures.get(index)));
                if response.hovered() {
                    pointed = Some(index);
                }
            }
            if !matches {
                let marked = if pixels.unexplained.is_some() && pixels.unexplained_pixels > 0 {
                    " (cyan in the difference)"
                } else {
                    ""
                };
                ui.label(format!(
                    "unexplained pixels: {}{marked}",
                    pixels.unexplained_pixels
                ));
            }
        }
        CompareSource::Quality(figures) => {
            ui.label(format!(
                "mean error {:.3} levels · off by > {OFF_LEVELS}: {:.2}% of pixels",
                figures.mean_error_levels,
                100.0 * figures.share_off
            ));
            if let Some((mean, share)) = figures.against_reference {
                ui.label(format!(
                    "against {REFERENCE_SAMPLES} samples: mean {mean:.3} levels · off by > \
                     {OFF_LEVELS}: {:.2}%",
                    100.0 * share
                ));
            }
            ui.label(format!(
                "frame {:.1} ms (exact {:.1} ms)",
                figures.frame_ms, figures.exact_ms
            ));
        }
    }
    if ui.button("Close comparison").clicked() {
        actions.push(Action::CompareClose);
    }
    state.point_at(&ui.ctx().clone(), pointed);
    actions
}

/// Heads the tip of a statement pointed at (tests find the tip by it).
pub(crate) const STATEMENT_TIP: &str = "what it means";

/// The tip of a statement pointed at: what it means and what to check, and its gallery picture.
fn statement_tip(
    ui: &mut Ui,
    deviation: &Deviation,
    picture: Option<&Option<egui::TextureHandle>>,
) {
    ui.set_max_width(420.0);
    ui.label(RichText::new(deviation.name_and_values()).strong());
    ui.label(RichText::new(STATEMENT_TIP).small());
    ui.label(deviation.explanation());
    if let Some(Some(texture)) = picture {
        ui.label(
            RichText::new("in the gallery (docs/mistakes.md): theirs, exact, difference").small(),
        );
        let size = texture.size_vec2();
        let scale = (400.0 / size.x).min(1.0);
        ui.image((texture.id(), size * scale));
    }
    ui.label(RichText::new("its pixels are in colour in the difference while pointed at").small());
}
