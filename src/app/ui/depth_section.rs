//! The side panel's depth section: colour map, the no-hit mark, "auto range" with its percentile
//! cut and a "follow" mode that keeps fitting while the view changes, the histogram's count
//! scale, and resetting the range to the file's.

use egui::Ui;

use crate::app::actions::Action;
use crate::app::depth_stats::MAX_PERCENTILE_CUT;
use crate::app::settings::DepthDisplay;
use crate::render::depth_map::DepthColourMap;

/// The side panel's depth section. Returns the actions asked for.
pub(crate) fn depth_tools_ui(ui: &mut Ui, display: &mut DepthDisplay) -> Vec<Action> {
    let mut actions = Vec::new();
    ui.horizontal(|ui| {
        ui.label("colour map");
        for map in DepthColourMap::ALL {
            ui.radio_value(&mut display.colour_map, map, map.name())
                .on_hover_text(match map {
                    DepthColourMap::Grey => "the course's grey ramp: near white, far black",
                    DepthColourMap::Turbo => "turbo: near red, far blue",
                    DepthColourMap::Viridis => "viridis: near yellow, far purple",
                });
        }
    });
    ui.checkbox(&mut display.mark_no_hit, "mark no-hit pixels")
        .on_hover_text(
            "show pixels where no ray hits in a colour the map does not use (dark blue on grey, light grey on turbo and viridis) instead of black; files keep black",
        );
    ui.horizontal(|ui| {
        if ui
            .button("Auto range")
            .on_hover_text("fit depth min and max to the t visible in the view (A)")
            .clicked()
        {
            actions.push(Action::AutoRange);
        }
        let label = ui.label("ignore % at each end");
        ui.add(
            egui::DragValue::new(&mut display.auto_cut_percent)
                .range(0.0..=MAX_PERCENTILE_CUT)
                .speed(0.1)
                .max_decimals(1),
        )
        .labelled_by(label.id)
        .on_hover_text("auto range leaves out this share of the visible t at each end (outliers)");
    });
    ui.horizontal(|ui| {
        ui.checkbox(&mut display.follow, "follow")
            .on_hover_text("keep fitting the range to the visible t while the view changes");
        ui.checkbox(&mut display.log_counts, "log counts")
            .on_hover_text("the histogram's bars on a logarithmic scale of the pixel counts");
        if ui
            .button("Reset depth")
            .on_hover_text("the depth range the file's view started with (D)")
            .clicked()
        {
            actions.push(Action::ResetDepth);
        }
    });
    super::hint::hint(ui, "drag the lines on the histogram to set the range");
    actions
}
