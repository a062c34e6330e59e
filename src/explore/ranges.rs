//! What an interactive viewer derives from a scene and a view, as plain math: the ranges its
//! sliders span (from the scene's bounds along each axis and along the view direction, never
//! hard-coded) and the depth range that brackets what the view can see.

use std::ops::RangeInclusive;

use glam::DVec3;

use crate::geometry::camera::CameraBasis;
use crate::render::View;
use crate::render::depth_map::DepthRange;
use crate::scene::{Bounds, MAX_MAGNITUDE, Scene};

/// The box the viewer explores: the spheres' bounds, or a unit box around the camera centre for
/// a scene without spheres. Never empty (a single point is grown to a unit box).
pub fn scene_extent(scene: &Scene) -> Bounds {
    let bounds = scene.bounds().unwrap_or(Bounds {
        min_world: scene.camera.center_world,
        max_world: scene.camera.center_world,
    });
    let diagonal = bounds.diagonal();
    if diagonal > 0.0 && diagonal.is_finite() {
        return bounds;
    }
    let center = bounds.center();
    Bounds {
        min_world: center - DVec3::splat(0.5),
        max_world: center + DVec3::splat(0.5),
    }
}

/// How far a slider reaches from the value its drag starts at, so that its step follows the
/// value (a slider spanning the whole scene moves a small view by whole screens per pixel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reach {
    /// `value − d ..= value + d`.
    Plus(f64),
    /// `value / f ..= value · f` (a logarithmic slider; `f` > 1).
    Times(f64),
}

/// A size slider reaches this factor either way: a drag across the whole slider scales the
/// view by 64.
pub const SIZE_REACH_FACTOR: f64 = 8.0;

/// The part of `range` a slider spans for a drag that starts at `value`: `value` reached by
/// `reach` either way, kept inside `range` (which always holds `value`, see [`SliderRanges`]).
/// A value that is not a usable number, or a reach that is not, gives `range` itself.
pub fn window_around(range: &RangeInclusive<f64>, value: f64, reach: Reach) -> RangeInclusive<f64> {
    let (low, high) = match reach {
        Reach::Plus(d) => (value - d, value + d),
        Reach::Times(f) => (value / f, value * f),
    };
    let usable = match reach {
        Reach::Plus(d) => d > 0.0,
        Reach::Times(f) => f > 1.0 && value > 0.0,
    };
    if !(usable && low.is_finite() && high.is_finite() && range.contains(&value)) {
        return range.clone();
    }
    low.max(*range.start())..=high.min(*range.end())
}

/// The ranges of the viewer's sliders for one scene and view.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderRanges {
    /// Camera centre x, y and z: the scene's extent along the axis, widened by the scene's
    /// diagonal on both sides (and by the current value, so it is never clamped).
    pub(crate) center_world: [RangeInclusive<f64>; 3],
    /// Screen size (logarithmic): from 1/1000 of the diagonal to 10 diagonals.
    pub(crate) size_world: RangeInclusive<f64>,
    /// Depth min and max: t of the scene's bounding sphere along the view direction, widened by
    /// half its radius on both sides.
    pub(crate) depth_t: RangeInclusive<f64>,
    /// How far a drag of a centre slider reaches: the view's size (two screens across the
    /// slider), or the scene's diagonal for an unusable size.
    pub(crate) center_reach: Reach,
    /// How far a drag of a depth slider reaches: the depth range's width (at least a hundredth
    /// of the depth slider's whole range), so a narrow range is tuned finely.
    pub(crate) depth_reach: Reach,
}

/// `range` widened to contain `value`, if `value` is a usable number (finite and at most
/// [`MAX_MAGNITUDE`] in magnitude; slider ranges stay where arithmetic cannot overflow).
fn widen_to(range: RangeInclusive<f64>, value: f64) -> RangeInclusive<f64> {
    if value.abs() <= MAX_MAGNITUDE {
        range.start().min(value)..=range.end().max(value)
    } else {
        range
    }
}

/// `range` if both ends are finite and ordered, else `fallback`.
fn finite_or(range: RangeInclusive<f64>, fallback: RangeInclusive<f64>) -> RangeInclusive<f64> {
    if range.start().is_finite() && range.end().is_finite() && range.start() <= range.end() {
        range
    } else {
        fallback
    }
}

impl SliderRanges {
    /// Ranges for `scene` seen through `view` (the view's values always lie inside).
    pub fn new(scene: &Scene, view: &View) -> Self {
        let extent = scene_extent(scene);
        let diagonal = extent.diagonal();
        let center_world = [0, 1, 2].map(|axis| {
            let range = extent.min_world[axis] - diagonal..=extent.max_world[axis] + diagonal;
            widen_to(range, view.center_world[axis])
        });
        let size_world = 1e-3 * diagonal..=10.0 * diagonal;
        let size_world = if view.size_world > 0.0 {
            widen_to(size_world, view.size_world)
        } else {
            size_world
        };
        let radius = 0.5 * diagonal;
        let depth_t = match CameraBasis::new(view.direction_world, view.up_world) {
            Ok(basis) => {
                let center_t = (extent.center() - view.center_world).dot(basis.direction);
                center_t - 1.5 * radius..=center_t + 1.5 * radius
            }
            Err(_) => -diagonal..=diagonal,
        };
        let depth_t = finite_or(depth_t, -diagonal..=diagonal);
        let depth_t = widen_to(
            widen_to(depth_t, view.depth_range.min_t),
            view.depth_range.max_t,
        );
        let size = view.size_world;
        let center_reach = if size > 0.0 && size <= MAX_MAGNITUDE {
            size
        } else {
            diagonal
        };
        let depth_width = (view.depth_range.max_t - view.depth_range.min_t).abs();
        let depth_floor = 0.01 * (depth_t.end() - depth_t.start());
        let depth_reach = if depth_width <= MAX_MAGNITUDE {
            depth_width.max(depth_floor)
        } else {
            depth_floor
        };
        Self {
            center_world,
            size_world,
            depth_t,
            center_reach: Reach::Plus(center_reach),
            depth_reach: Reach::Plus(depth_reach),
        }
    }
}

/// The t range that brackets every visible surface point: from the nearest sphere front
/// (`t_center − r`) to the farthest silhouette (`t_center`, where the front surface meets the
/// outline). For scene1_01 this is the course's own `-depth 9 10`. `None` without spheres or
/// for an unusable view.
pub fn visible_depth_range(scene: &Scene, view: &View) -> Option<DepthRange> {
    let basis = CameraBasis::new(view.direction_world, view.up_world).ok()?;
    let mut range: Option<DepthRange> = None;
    for sphere in &scene.spheres {
        let t_center = (sphere.center_world - view.center_world).dot(basis.direction);
        let near = t_center - sphere.radius_world;
        range = Some(match range {
            None => DepthRange::new(near, t_center),
            Some(r) => DepthRange::new(r.min_t.min(near), r.max_t.max(t_center)),
        });
    }
    range.filter(|r| r.min_t.is_finite() && r.max_t.is_finite())
}

/// The depth range a viewer starts with: [`visible_depth_range`], or `[0, 1]` without spheres.
pub fn initial_depth_range(scene: &Scene, view: &View) -> DepthRange {
    visible_depth_range(scene, view).unwrap_or(DepthRange::new(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;

    fn course_scene_1_01() -> Scene {
        parse_scene(
            "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }
             Materials { numMaterials 1 PhongMaterial { diffuseColor 1 0 0 } }
             Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } }",
        )
        .unwrap()
    }

    #[test]
    fn visible_range_of_scene1_01_is_the_course_range() {
        let scene = course_scene_1_01();
        let view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(0.0, 1.0));
        assert_eq!(
            visible_depth_range(&scene, &view),
            Some(DepthRange::new(9.0, 10.0))
        );
    }

    #[test]
    fn ranges_come_from_the_scene_and_contain_the_view() {
        let scene = course_scene_1_01();
        let view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(9.0, 10.0));
        let ranges = SliderRanges::new(&scene, &view);
        let diagonal = 2.0 * 3f64.sqrt();
        assert_eq!(ranges.center_world[0], -1.0 - diagonal..=1.0 + diagonal);
        // The camera's z = 10 lies outside the scene's box: the range widens to contain it.
        assert_eq!(*ranges.center_world[2].end(), 10.0);
        assert!(ranges.size_world.contains(&5.0));
        assert!(ranges.depth_t.contains(&9.0) && ranges.depth_t.contains(&10.0));
        // Depth slider centred on the scene's centre t (10).
        assert!((ranges.depth_t.start() + ranges.depth_t.end() - 20.0).abs() < 1e-12);
    }

    #[test]
    fn a_drag_reaches_as_far_as_the_view_not_the_whole_scene() {
        let scene = course_scene_1_01();
        let view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(9.0, 10.0));
        let ranges = SliderRanges::new(&scene, &view);
        // Centre: the view's size (5) either way; depth: the range's width (1).
        assert_eq!(ranges.center_reach, Reach::Plus(5.0));
        assert_eq!(ranges.depth_reach, Reach::Plus(1.0));
        assert_eq!(
            window_around(&ranges.center_world[0], 0.5, Reach::Plus(2.0)),
            -1.5..=2.5
        );
        // Kept inside the whole range: ±5 around 0 is cut to the scene's ±(1 + diagonal).
        assert_eq!(
            window_around(&ranges.center_world[0], 0.0, ranges.center_reach),
            ranges.center_world[0]
        );
        assert_eq!(
            window_around(&ranges.depth_t, 9.0, ranges.depth_reach),
            8.0..=10.0
        );
        assert_eq!(
            window_around(&ranges.size_world, 2.0, Reach::Times(SIZE_REACH_FACTOR)),
            0.25..=16.0
        );
        // Kept inside the whole range: the size slider stops at ten diagonals.
        let ten_diagonals = 20.0 * 3f64.sqrt();
        assert_eq!(
            window_around(&ranges.size_world, 5.0, Reach::Times(SIZE_REACH_FACTOR)),
            0.625..=ten_diagonals
        );
        // A value outside the range, or an unusable one, gets the whole range.
        for value in [f64::NAN, 1e6, -1.0] {
            assert_eq!(
                window_around(&ranges.size_world, value, Reach::Times(SIZE_REACH_FACTOR)),
                ranges.size_world
            );
        }
    }

    #[test]
    fn hostile_views_still_give_finite_ordered_ranges() {
        let scene = course_scene_1_01();
        let good = View::of_camera(&scene.camera, 10, 10, DepthRange::new(9.0, 10.0));
        for value in [f64::NAN, f64::INFINITY, -1e308, 1e308, 0.0, -5.0] {
            let view = View {
                center_world: DVec3::splat(value),
                size_world: value,
                depth_range: DepthRange::new(value, -value),
                direction_world: DVec3::new(value, 1.0, -1.0),
                ..good
            };
            let ranges = SliderRanges::new(&scene, &view);
            let all = ranges
                .center_world
                .iter()
                .chain([&ranges.size_world, &ranges.depth_t]);
            for range in all {
                assert!(
                    range.start().is_finite() && range.end().is_finite(),
                    "{value}: {range:?}"
                );
                assert!(range.start() <= range.end());
            }
            assert!(
                *ranges.size_world.start() > 0.0,
                "logarithmic size range stays positive"
            );
        }
    }

    #[test]
    fn empty_scene_gets_a_unit_box_around_the_camera() {
        let scene =
            parse_scene("OrthographicCamera { center 1 2 3 direction 0 0 -1 up 0 1 0 size 5 }")
                .unwrap();
        let extent = scene_extent(&scene);
        assert_eq!(extent.center(), DVec3::new(1.0, 2.0, 3.0));
        assert!(extent.diagonal() > 0.0);
        let view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(0.0, 1.0));
        assert_eq!(
            initial_depth_range(&scene, &view),
            DepthRange::new(0.0, 1.0)
        );
    }
}
