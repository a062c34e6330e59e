//! The histogram of visible t under the depth image: the depth range drawn on it with its two
//! ends draggable, a legend strip of the colour map below it, and the axis labels. The statistics
//! themselves are in [`crate::explore::depth_stats`].

use egui::{Color32, CursorIcon, Pos2, Rect, Sense, Stroke, Ui, Vec2};

use super::probe_text::short_number;
use crate::explore::depth_stats::DepthHistogram;
use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Height of the histogram block (bars, legend strip and labels), in points.
pub(crate) const HISTOGRAM_POINTS: f32 = 88.0;

/// Height of the bars, in points.
const BARS_POINTS: f32 = 46.0;

/// Height of the legend strip under the bars, in points.
const LEGEND_POINTS: f32 = 10.0;

/// Half width of a handle's grab area, in points.
const HANDLE_HALF_WIDTH_POINTS: f32 = 6.0;

/// Accessible labels of the two handles (tests find them by these).
pub const MIN_HANDLE_LABEL: &str = "depth min handle";
/// See [`MIN_HANDLE_LABEL`].
pub const MAX_HANDLE_LABEL: &str = "depth max handle";

/// The t interval the histogram's x axis spans: the visible t and the depth range, with a
/// little room on each side so both ends can be grabbed.
pub fn histogram_axis(histogram: &DepthHistogram, range: &DepthRange) -> (f64, f64) {
    let mut low = histogram.t_low;
    let mut high = histogram.t_high;
    for t in [range.min_t, range.max_t] {
        if t.is_finite() {
            low = low.min(t);
            high = high.max(t);
        }
    }
    if !(high - low).is_finite() {
        // A range end so far out that the axis would be infinite: the axis shows the visible t
        // only, and that handle sits at the edge.
        low = histogram.t_low;
        high = histogram.t_high;
    }
    let span = high - low;
    let pad = if span > 0.0 {
        0.04 * span
    } else {
        (low.abs() * 1e-3).max(1e-9)
    };
    (low - pad, high + pad)
}

/// Where the histogram's parts are drawn and how its x axis maps t.
struct Layout {
    /// The whole block (bars, legend, labels).
    block: Rect,
    /// The bars.
    bars: Rect,
    /// The colour-map strip under the bars.
    legend: Rect,
    /// The t at the axis's left and right ends.
    axis_low: f64,
    axis_high: f64,
}

impl Layout {
    fn new(block: Rect, histogram: &DepthHistogram, range: &DepthRange) -> Self {
        let width = block.width();
        let bars = Rect::from_min_size(
            Pos2::new(block.left(), block.top() + 4.0),
            Vec2::new(width, BARS_POINTS),
        );
        let legend = Rect::from_min_size(
            Pos2::new(block.left(), bars.bottom() + 2.0),
            Vec2::new(width, LEGEND_POINTS),
        );
        let (axis_low, axis_high) = histogram_axis(histogram, range);
        Self {
            block,
            bars,
            legend,
            axis_low,
            axis_high,
        }
    }

    /// The x of `t` on the axis.
    fn x_of(&self, t: f64) -> f32 {
        let share = (t - self.axis_low) / (self.axis_high - self.axis_low);
        self.bars.left() + share as f32 * self.bars.width()
    }

    /// The t at `x` on the axis.
    fn t_of(&self, x: f32) -> f64 {
        let share = f64::from((x - self.bars.left()) / self.bars.width());
        self.axis_low + share * (self.axis_high - self.axis_low)
    }
}

/// The histogram with the range on it; dragging a handle sets that end of `range` to the t under
/// the pointer (within the axis). Returns true when a handle moved the range.
pub(crate) fn histogram_ui(
    ui: &mut Ui,
    histogram: Option<&DepthHistogram>,
    range: &mut DepthRange,
    colour_map: DepthColourMap,
    no_hit_rgb: [u8; 3],
) -> bool {
    let width = ui.available_width();
    let (block, _) = ui.allocate_exact_size(Vec2::new(width, HISTOGRAM_POINTS), Sense::hover());
    let Some(histogram) = histogram else {
        ui.painter().text(
            block.left_top() + Vec2::new(0.0, 4.0),
            egui::Align2::LEFT_TOP,
            "no sphere visible: nothing to histogram",
            egui::FontId::proportional(12.0),
            ui.visuals().weak_text_color(),
        );
        return false;
    };
    let layout = Layout::new(block, histogram, range);
    let painter = ui.painter_at(block);
    paint_bars(ui, &painter, &layout, histogram);
    paint_legend(&painter, &layout, range, colour_map, no_hit_rgb);
    let moved = range_handles_ui(ui, &painter, &layout, range);
    paint_labels(ui, &painter, &layout, histogram, no_hit_rgb);
    moved
}

/// Bars: each bin from its t interval, height by count relative to the tallest bin.
fn paint_bars(ui: &Ui, painter: &egui::Painter, layout: &Layout, histogram: &DepthHistogram) {
    let bars = layout.bars;
    painter.rect_filled(bars, 0.0, ui.visuals().extreme_bg_color);
    let tallest = histogram.max_count().max(1) as f32;
    let bin_width_t = histogram.bin_width();
    let bar_colour = ui.visuals().text_color().gamma_multiply(0.7);
    for (bin, &count) in histogram.counts.iter().enumerate() {
        if count == 0 {
            continue;
        }
        let t0 = histogram.t_low + bin as f64 * bin_width_t;
        let x0 = layout.x_of(t0);
        let x1 = layout.x_of(t0 + bin_width_t).max(x0 + 1.0);
        let height = (count as f32 / tallest).sqrt() * BARS_POINTS;
        let bar = Rect::from_min_max(
            Pos2::new(x0, bars.bottom() - height),
            Pos2::new(x1, bars.bottom()),
        );
        painter.rect_filled(bar, 0.0, bar_colour);
    }
}

/// Legend: the colour each t of the axis gets.
fn paint_legend(
    painter: &egui::Painter,
    layout: &Layout,
    range: &DepthRange,
    colour_map: DepthColourMap,
    no_hit_rgb: [u8; 3],
) {
    let legend = layout.legend;
    let columns = (legend.width() / 2.0).ceil() as usize;
    for column in 0..columns {
        let x = legend.left() + column as f32 * 2.0;
        let [r, g, b] = colour_map.rgb(range, layout.t_of(x + 1.0), no_hit_rgb);
        painter.rect_filled(
            Rect::from_min_size(Pos2::new(x, legend.top()), Vec2::new(2.0, LEGEND_POINTS)),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
}

/// The range's two ends, each a draggable line. Returns true when one moved.
fn range_handles_ui(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    range: &mut DepthRange,
) -> bool {
    let (bars, legend) = (layout.bars, layout.legend);
    let mut moved = false;
    let accent = ui.visuals().selection.stroke.color;
    for (is_min, label) in [(true, MIN_HANDLE_LABEL), (false, MAX_HANDLE_LABEL)] {
        let t = if is_min { range.min_t } else { range.max_t };
        // NaN (a degenerate axis) puts the handle at the left edge: widget rects must be numbers.
        let x = match layout.x_of(t) {
            x if x.is_nan() => bars.left(),
            x => x.clamp(bars.left(), bars.right()),
        };
        let grab = Rect::from_min_max(
            Pos2::new(x - HANDLE_HALF_WIDTH_POINTS, bars.top()),
            Pos2::new(x + HANDLE_HALF_WIDTH_POINTS, legend.bottom()),
        );
        let response = ui
            .interact(grab, ui.make_persistent_id(label), Sense::drag())
            .on_hover_cursor(CursorIcon::ResizeHorizontal);
        response
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Slider, true, label.to_owned()));
        let stroke_width = if response.hovered() || response.dragged() {
            3.0
        } else {
            2.0
        };
        painter.line_segment(
            [Pos2::new(x, bars.top()), Pos2::new(x, legend.bottom())],
            Stroke::new(stroke_width, accent),
        );
        if response.dragged()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let t = layout.t_of(pointer.x.clamp(bars.left(), bars.right()));
            if is_min {
                range.min_t = t;
            } else {
                range.max_t = t;
            }
            moved = true;
        }
    }
    moved
}

/// The axis's end labels, the pixel counts, and a swatch of the no-hit colour.
fn paint_labels(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    histogram: &DepthHistogram,
    no_hit_rgb: [u8; 3],
) {
    let block = layout.block;
    let label_y = layout.legend.bottom() + 2.0;
    let font = egui::FontId::proportional(11.0);
    let weak = ui.visuals().weak_text_color();
    painter.text(
        Pos2::new(block.left(), label_y),
        egui::Align2::LEFT_TOP,
        format!("t {}", short_number(layout.axis_low)),
        font.clone(),
        weak,
    );
    painter.text(
        Pos2::new(block.right(), label_y),
        egui::Align2::RIGHT_TOP,
        format!("t {}", short_number(layout.axis_high)),
        font.clone(),
        weak,
    );
    let counts = format!(
        "{} visible px · {} no-hit px",
        histogram.total(),
        histogram.no_hit
    );
    let text_rect = painter.text(
        Pos2::new(block.center().x, label_y),
        egui::Align2::CENTER_TOP,
        counts,
        font,
        weak,
    );
    let [r, g, b] = no_hit_rgb;
    painter.rect_filled(
        Rect::from_min_size(
            Pos2::new(text_rect.right() + 4.0, text_rect.top() + 2.0),
            Vec2::splat(text_rect.height() - 4.0),
        ),
        0.0,
        Color32::from_rgb(r, g, b),
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_axis_holds_the_visible_t_and_the_range() {
        let histogram = DepthHistogram {
            t_low: 9.0,
            t_high: 11.0,
            counts: vec![1, 2],
            no_hit: 0,
        };
        let (low, high) = histogram_axis(&histogram, &DepthRange::new(10.0, 20.0));
        assert!(low < 9.0 && high > 20.0);
        let (low, high) = histogram_axis(&histogram, &DepthRange::new(9.5, 10.5));
        assert!(low < 9.0 && low > 8.8 && high > 11.0 && high < 11.2);
        // A single t still gives an axis of some width.
        let single = DepthHistogram {
            t_low: 5.0,
            t_high: 5.0,
            counts: vec![3],
            no_hit: 1,
        };
        let (low, high) = histogram_axis(&single, &DepthRange::new(5.0, 5.0));
        assert!(low < 5.0 && high > 5.0);
        // Range ends at ±1e308 (typed by hand) would make the axis infinite: it keeps the
        // visible t, finite.
        let (low, high) = histogram_axis(&histogram, &DepthRange::new(-1e308, 1e308));
        assert!(low.is_finite() && high.is_finite() && low < 9.0 && high > 11.0);
    }
}
