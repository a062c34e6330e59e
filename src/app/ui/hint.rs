//! The hint under a control: what it does, what to try.

/// The size of hint text (what a control does, what to try), points: egui's small text (9 points)
/// was hard to read.
pub(crate) const HINT_POINTS: f32 = 12.0;

/// A hint under a control: italic, at [`HINT_POINTS`], in the normal text colour (egui's weak
/// colour had too little contrast against the panel).
pub(crate) fn hint(ui: &mut egui::Ui, text: &str) -> egui::Response {
    let colour = ui.visuals().text_color().gamma_multiply(0.85);
    ui.label(
        egui::RichText::new(text)
            .italics()
            .size(HINT_POINTS)
            .color(colour),
    )
}
