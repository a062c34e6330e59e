//! The histogram of visible t under the depth image: the depth range drawn on it, its two ends
//! draggable and labelled with their t, a legend strip of the colour map, the axis's end labels
//! (never overlapping: a label that would touch another is left out) and, under the pointer, the
//! t and the pixel count of the bar there. The axis fits the t visible in the frame, so it follows
//! zoom and pan; a range end outside it sits at the edge, marked with an arrow. Counts can be
//! drawn on a logarithmic scale. The statistics themselves are in
//! [`crate::app::depth_stats`].

use egui::{Align2, Color32, CursorIcon, FontId, Pos2, Rect, Sense, Stroke, Ui, Vec2};

use crate::app::depth_stats::DepthHistogram;
use crate::export::numbers::{decimals_for_span, grouped, range_ends, with_decimals};
use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Height of the legend strip under the bars, in points.
const LEGEND_POINTS: f32 = 8.0;

/// Height of a line of labels, in points.
const LABEL_POINTS: f32 = 14.0;

/// Half width of a handle's grab area, in points.
const HANDLE_HALF_WIDTH_POINTS: f32 = 6.0;

/// Font size of the labels, in points.
const LABEL_FONT_POINTS: f32 = 11.0;

/// Accessible labels of the two handles (tests find them by these).
pub const MIN_HANDLE_LABEL: &str = "depth min handle";
/// See [`MIN_HANDLE_LABEL`].
pub const MAX_HANDLE_LABEL: &str = "depth max handle";

/// How the histogram is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HistogramStyle {
    /// Bar heights on a logarithmic scale of the counts (else the square root).
    pub(crate) log_counts: bool,
    /// The block's height, points.
    pub(crate) height: f32,
}

impl HistogramStyle {
    /// The same style in a block `height` points high.
    pub(crate) fn with_height(self, height: f32) -> Self {
        Self { height, ..self }
    }
}

/// The t interval the histogram's x axis spans: the visible t, with a little room on each side
/// so that ends at the edge can be grabbed.
pub fn histogram_axis(histogram: &DepthHistogram, _range: &DepthRange) -> (f64, f64) {
    let (low, high) = (histogram.t_low, histogram.t_high);
    let span = high - low;
    let pad = if span > 0.0 && span.is_finite() {
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
        // Labels of the range's ends above the bars, the axis's below the legend.
        let bars_height = (block.height() - 2.0 * LABEL_POINTS - LEGEND_POINTS - 4.0).max(8.0);
        let bars = Rect::from_min_size(
            Pos2::new(block.left(), block.top() + LABEL_POINTS),
            Vec2::new(width, bars_height),
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
    style: HistogramStyle,
    colour_map: DepthColourMap,
    no_hit_rgb: [u8; 3],
) -> bool {
    let width = ui.available_width();
    let (block, response) = ui.allocate_exact_size(Vec2::new(width, style.height), Sense::hover());
    let Some(histogram) = histogram else {
        ui.painter().text(
            block.left_top() + Vec2::new(0.0, 4.0),
            Align2::LEFT_TOP,
            "no sphere visible: nothing to histogram",
            FontId::proportional(12.0),
            ui.visuals().weak_text_color(),
        );
        return false;
    };
    let layout = Layout::new(block, histogram, range);
    let painter = ui.painter_at(block);
    paint_bars(ui, &painter, &layout, histogram, style.log_counts);
    paint_legend(&painter, &layout, range, colour_map, no_hit_rgb);
    let mut labels = Labels::default();
    let moved = range_handles_ui(ui, &painter, &layout, range, &mut labels);
    paint_axis_labels(ui, &painter, &layout, histogram, no_hit_rgb, &mut labels);
    // Kept for the tests and tools that check the labels never overlap.
    ui.ctx()
        .data_mut(|data| data.insert_temp(labels_id(), labels.placed.clone()));
    if let Some(pointer) = response.hover_pos() {
        paint_hover_readout(ui, &painter, &layout, histogram, pointer);
    }
    moved
}

/// Bars: each bin from its t interval, height by count relative to the tallest bin (square root
/// or logarithm of the count, so small bins stay visible).
fn paint_bars(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    histogram: &DepthHistogram,
    log_counts: bool,
) {
    let bars = layout.bars;
    painter.rect_filled(bars, 0.0, ui.visuals().extreme_bg_color);
    let scale = |count: u32| {
        if log_counts {
            (1.0 + f64::from(count)).ln() as f32
        } else {
            (count as f32).sqrt()
        }
    };
    let tallest = scale(histogram.max_count().max(1));
    let bin_width_t = histogram.bin_width();
    let bar_colour = ui.visuals().text_color().gamma_multiply(0.7);
    for (bin, &count) in histogram.counts.iter().enumerate() {
        if count == 0 {
            continue;
        }
        let t0 = histogram.t_low + bin as f64 * bin_width_t;
        let x0 = layout.x_of(t0);
        let x1 = layout.x_of(t0 + bin_width_t).max(x0 + 1.0);
        let height = scale(count) / tallest * bars.height();
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

fn labels_id() -> egui::Id {
    egui::Id::unique("histogram labels")
}

/// Where the histogram's labels were drawn in the last pass (for tests and tools).
pub fn histogram_label_rects(ctx: &egui::Context) -> Vec<Rect> {
    ctx.data(|data| data.get_temp::<Vec<Rect>>(labels_id()))
        .unwrap_or_default()
}

/// The rectangles of the labels drawn so far: a new label that would overlap one is left out.
#[derive(Default)]
struct Labels {
    placed: Vec<Rect>,
}

impl Labels {
    /// Draws `text` anchored at `at` unless it would overlap a label already drawn (or leave
    /// `bounds`); returns whether it was drawn.
    fn place(
        &mut self,
        painter: &egui::Painter,
        at: Pos2,
        anchor: Align2,
        text: &str,
        colour: Color32,
        bounds: Rect,
    ) -> Option<Rect> {
        let font = FontId::proportional(LABEL_FONT_POINTS);
        let galley = painter.layout_no_wrap(text.to_owned(), font, colour);
        let mut rect = anchor.anchor_size(at, galley.size());
        // Keep it inside the block.
        let shift_x =
            (bounds.left() - rect.left()).max(0.0) + (bounds.right() - rect.right()).min(0.0);
        rect = rect.translate(Vec2::new(shift_x, 0.0));
        if self
            .placed
            .iter()
            .any(|other| other.expand(2.0).intersects(rect))
        {
            return None;
        }
        painter.galley(rect.min, galley, colour);
        self.placed.push(rect);
        Some(rect)
    }
}

/// The range's two ends, each a draggable line labelled with its t; an end outside the axis
/// sits at the edge with an arrow. Returns true when one moved.
fn range_handles_ui(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    range: &mut DepthRange,
    labels: &mut Labels,
) -> bool {
    let (bars, legend) = (layout.bars, layout.legend);
    let mut moved = false;
    let accent = ui.visuals().selection.stroke.color;
    let ends = range_ends(range.min_t, range.max_t);
    for (is_min, label) in [(true, MIN_HANDLE_LABEL), (false, MAX_HANDLE_LABEL)] {
        let t = if is_min { range.min_t } else { range.max_t };
        let shown_t = &ends[usize::from(!is_min)];
        // NaN (a degenerate axis) puts the handle at the left edge: widget rects must be numbers.
        let raw_x = layout.x_of(t);
        let x = if raw_x.is_nan() {
            bars.left()
        } else {
            raw_x.clamp(bars.left(), bars.right())
        };
        let outside = raw_x.is_nan() || raw_x < bars.left() || raw_x > bars.right();
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
        let name = if is_min { "min" } else { "max" };
        let arrow = match (outside, raw_x < bars.left()) {
            (true, true) => "< ",
            (true, false) => "> ",
            _ => "",
        };
        let text = format!("{arrow}{name} {shown_t}");
        let anchor = if x < bars.center().x {
            Align2::LEFT_BOTTOM
        } else {
            Align2::RIGHT_BOTTOM
        };
        let at = Pos2::new(x, bars.top());
        let placed = labels.place(painter, at, anchor, &text, accent, layout.block);
        if placed.is_none() {
            // Both ends close together: the second label goes on the other side of its line.
            let flipped = if anchor == Align2::LEFT_BOTTOM {
                Align2::RIGHT_BOTTOM
            } else {
                Align2::LEFT_BOTTOM
            };
            labels.place(painter, at, flipped, &text, accent, layout.block);
        }
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

/// The axis's end labels, the pixel counts and a swatch of the no-hit colour, each left out
/// where it would overlap another label.
fn paint_axis_labels(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    histogram: &DepthHistogram,
    no_hit_rgb: [u8; 3],
    labels: &mut Labels,
) {
    let block = layout.block;
    let y = layout.legend.bottom() + 2.0;
    let weak = ui.visuals().weak_text_color();
    let [low, high] = range_ends(layout.axis_low, layout.axis_high).map(|end| format!("t {end}"));
    labels.place(
        painter,
        Pos2::new(block.left(), y),
        Align2::LEFT_TOP,
        &low,
        weak,
        block,
    );
    labels.place(
        painter,
        Pos2::new(block.right(), y),
        Align2::RIGHT_TOP,
        &high,
        weak,
        block,
    );
    let counts = format!(
        "{} px · {} no hit",
        grouped(histogram.total() as f64, 0),
        grouped(histogram.no_hit as f64, 0)
    );
    let at = Pos2::new(block.center().x, y);
    if let Some(rect) = labels.place(painter, at, Align2::CENTER_TOP, &counts, weak, block) {
        let [r, g, b] = no_hit_rgb;
        painter.rect_filled(
            Rect::from_min_size(
                Pos2::new(rect.right() + 4.0, rect.top() + 2.0),
                Vec2::splat((rect.height() - 4.0).max(2.0)),
            ),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
}

/// Under the pointer: the t there and how many pixels its bar holds.
fn paint_hover_readout(
    ui: &Ui,
    painter: &egui::Painter,
    layout: &Layout,
    histogram: &DepthHistogram,
    pointer: Pos2,
) {
    if !layout.bars.contains(pointer) {
        return;
    }
    let t = layout.t_of(pointer.x);
    let bin = ((t - histogram.t_low) / histogram.bin_width()).floor();
    let count = if bin >= 0.0 && (bin as usize) < histogram.counts.len() {
        histogram.counts[bin as usize]
    } else {
        0
    };
    let decimals = decimals_for_span(layout.axis_high - layout.axis_low);
    let text = format!(
        "t {} · {} px",
        with_decimals(t, decimals),
        grouped(count as f64, 0)
    );
    painter.line_segment(
        [
            Pos2::new(pointer.x, layout.bars.top()),
            Pos2::new(pointer.x, layout.bars.bottom()),
        ],
        Stroke::new(1.0, ui.visuals().weak_text_color()),
    );
    let anchor = if pointer.x < layout.bars.center().x {
        Align2::LEFT_TOP
    } else {
        Align2::RIGHT_TOP
    };
    let font = FontId::proportional(LABEL_FONT_POINTS);
    let galley = painter.layout_no_wrap(text, font, ui.visuals().strong_text_color());
    let rect = anchor.anchor_size(
        Pos2::new(pointer.x + 4.0, layout.bars.top() + 2.0),
        galley.size(),
    );
    painter.rect_filled(rect.expand(2.0), 2.0, ui.visuals().extreme_bg_color);
    painter.galley(rect.min, galley, ui.visuals().strong_text_color());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_axis_holds_the_visible_t() {
        let histogram = DepthHistogram {
            t_low: 9.0,
            t_high: 11.0,
            counts: vec![1, 2],
            no_hit: 0,
        };
        // The range does not widen the axis: it follows what is visible.
        let (low, high) = histogram_axis(&histogram, &DepthRange::new(10.0, 20.0));
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
        // Range ends at ±1e308 (typed by hand) leave it finite.
        let (low, high) = histogram_axis(&histogram, &DepthRange::new(-1e308, 1e308));
        assert!(low.is_finite() && high.is_finite() && low < 9.0 && high > 11.0);
    }
}
