//! The side panel's depth section: colour map, the no-hit mark, and "auto range" with its
//! percentile cut.

use egui::{RichText, Ui};

use crate::app::state::DepthDisplay;
use crate::explore::depth_stats::MAX_PERCENTILE_CUT;
use crate::render::depth_map::DepthColourMap;

/// What the depth section asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct DepthToolRequests {
    /// Fit the depth range to the visible t now.
    pub(crate) auto_range: bool,
}

/// The side panel's depth section: colour map, no-hit mark, auto range with its percentile cut.
pub(crate) fn depth_tools_ui(ui: &mut Ui, display: &mut DepthDisplay) -> DepthToolRequests {
    let mut requests = DepthToolRequests::default();
    ui.horizontal(|ui| {
        ui.label("colour map");
        for map in DepthColourMap::ALL {
            ui.radio_value(&mut display.colour_map, map, map.name());
        }
    });
    ui.checkbox(&mut display.mark_no_hit, "mark no-hit pixels")
        .on_hover_text(
            "show pixels where no ray hits in dark blue instead of black (files keep black)",
        );
    ui.horizontal(|ui| {
        if ui
            .button("Auto range")
            .on_hover_text("fit depth min and max to the t visible in the view (A)")
            .clicked()
        {
            requests.auto_range = true;
        }
        let label = ui.label("ignore % at each end");
        ui.add(
            egui::DragValue::new(&mut display.auto_cut_percent)
                .range(0.0..=MAX_PERCENTILE_CUT)
                .speed(0.1)
                .max_decimals(1),
        )
        .labelled_by(label.id);
    });
    ui.label(
        RichText::new("drag the lines on the histogram to set the range")
            .small()
            .weak(),
    );
    requests
}
