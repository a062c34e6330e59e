//! The probe under the images: what the pinned and the hovered pixel show (wrapped, scrolled
//! when they do not fit), a button to copy it as text and one to release the pin.

use egui::{RichText, Sense, Ui, Vec2};

/// What the probe's buttons asked for.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct ProbeAsked {
    /// "Unpin" was clicked.
    pub(crate) unpin: bool,
    /// "Trace" was clicked.
    pub(crate) trace: bool,
}

/// Font size of the probe's lines, in points.
const PROBE_FONT_POINTS: f32 = 11.0;

/// Width kept on the right of the probe for its buttons, points.
const BUTTONS_POINTS: f32 = 52.0;

/// The probe's lines in a block `height` points high: the lines on the left, wrapped to its
/// width and scrolled (the scroll bar shown whenever they do not fit), the buttons on the right.
/// Returns the buttons clicked.
pub(crate) fn probe_ui(ui: &mut Ui, lines: &[String], has_pin: bool, height: f32) -> ProbeAsked {
    let (rect, _) = ui.allocate_exact_size(Vec2::new(ui.available_width(), height), Sense::hover());
    let (text_rect, buttons_rect) = rect.split_left_right_at_x(rect.right() - BUTTONS_POINTS);
    let mut asked = ProbeAsked::default();
    // The buttons apart from the lines, so they stay put while the hover lines come and go.
    let mut buttons = ui.new_child(
        egui::UiBuilder::new()
            .max_rect(buttons_rect)
            .layout(egui::Layout::top_down(egui::Align::Max)),
    );
    if has_pin
        && buttons
            .small_button("Unpin")
            .on_hover_text("Release the pinned pixel (Escape)")
            .clicked()
    {
        asked.unpin = true;
    }
    if has_pin
        && buttons
            .small_button("Trace")
            .on_hover_text(
                "the course's computation behind the pinned pixel: ray, each sphere's roots, \
                 hit, colour, depth grey (as -trace X Y prints it)",
            )
            .clicked()
    {
        asked.trace = true;
    }
    if !lines.is_empty()
        && buttons
            .small_button("Copy")
            .on_hover_text("Copy the probe's lines as text")
            .clicked()
    {
        ui.ctx().copy_text(lines.join("\n"));
    }
    let mut text = ui.new_child(egui::UiBuilder::new().max_rect(text_rect));
    // A solid scroll bar, always drawn when the lines do not fit (a floating one shows only
    // under the pointer, and the lines looked cut).
    text.spacing_mut().scroll = egui::style::ScrollStyle::solid();
    if lines.is_empty() {
        super::hint::hint(
            &mut text,
            "hover an image to probe a pixel; click to pin it",
        );
    }
    egui::ScrollArea::vertical()
        .id_salt("probe lines")
        .auto_shrink([false, false])
        .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::VisibleWhenNeeded)
        .show(&mut text, |ui| {
            ui.spacing_mut().item_spacing.y = 0.0;
            for line in lines {
                ui.add(
                    egui::Label::new(RichText::new(line).monospace().size(PROBE_FONT_POINTS))
                        .wrap(),
                );
            }
        });
    asked
}
