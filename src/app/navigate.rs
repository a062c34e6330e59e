//! Navigation as plain math on a [`View`]: pan in the screen plane, zoom anchored at a point of
//! the image, orbit the view direction around a pivot, and "frame all". The viewer's mouse and
//! keyboard handlers call these; nothing here knows about a UI.
//!
//! Positions on the image are given in **image pixels with y up** (`(0, 0)` the bottom-left
//! corner of the image, `(W, H)` the top-right), so they map directly to the camera's screen
//! coordinates through [`crate::geometry::camera::PixelGrid`]. Every function returns the view unchanged
//! when the input view cannot be rendered (no basis) or the request is not a finite number, so a
//! stray event can never turn a good view into NaN.

use glam::{DQuat, DVec2, DVec3};

use crate::explore::scene_extent;
use crate::render::View;
use crate::scene::{MAX_MAGNITUDE, MIN_VIEW_SIZE, Scene};

/// A move of the view or the magnifier, from the keyboard or a gesture on the images.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Navigation {
    /// Pan by this many image pixels (y up), as [`pan`].
    Pan(DVec2),
    /// Orbit around the scene's centre: yaw as a drag to the right, pitch up (radians).
    Orbit(DVec2),
    /// Zoom by this factor (the size multiplied) at this image position (pixels, y up).
    ZoomAt(f64, DVec2),
    /// Magnify the images by this factor at this image position (no new render).
    Magnify(f64, DVec2),
    /// Move the magnified part by this many image pixels.
    PanMagnifier(DVec2),
    /// The pointer is over this image position, or over neither image.
    Hover(Option<DVec2>),
}

/// Margin "frame all" leaves around the scene, as a fraction of the screen (5% on each side).
pub(crate) const FRAME_ALL_MARGIN: f64 = 0.05;

/// Moves the camera centre in the screen plane so that the picture follows a drag of
/// `drag_px` image pixels (x right, y up): the world point under the cursor stays under it.
/// t values (and so the depth range) are unchanged: the centre moves perpendicular to the view
/// direction.
pub(crate) fn pan(view: &View, drag_px: DVec2) -> View {
    let Ok(basis) = view.validate() else {
        return *view;
    };
    if !drag_px.is_finite() {
        return *view;
    }
    let pixel_size_world = view.grid().pixel_size_world;
    let offset_world = -(drag_px.x * pixel_size_world) * basis.horizontal
        - (drag_px.y * pixel_size_world) * basis.screen_up;
    with_center(view, view.center_world + offset_world)
}

/// Scales the screen size by `factor` (< 1 zooms in) keeping the world point under
/// `anchor_px` (image pixels, y up) where it is on the image. The size stays in
/// `[1e-150, 1e150]`; a factor that would leave that range is cut to its edge.
pub(crate) fn zoom_at(view: &View, factor: f64, anchor_px: DVec2) -> View {
    let Ok(basis) = view.validate() else {
        return *view;
    };
    if !(factor.is_finite() && factor > 0.0 && anchor_px.is_finite()) {
        return *view;
    }
    let grid = view.grid();
    let (anchor_u, anchor_v) = grid.screen_of_pixel_point(anchor_px.x, anchor_px.y);
    let size_world = (view.size_world * factor).clamp(MIN_VIEW_SIZE, MAX_MAGNITUDE);
    let applied = size_world / view.size_world;
    // The anchor's screen offset scales with the size; move the centre to keep its world point.
    let shift = (1.0 - applied) * (anchor_u * basis.horizontal + anchor_v * basis.screen_up);
    View {
        size_world,
        ..with_center(view, view.center_world + shift)
    }
}

/// Rotates the camera around `pivot_world`: `yaw_rad` turns about the screen's up axis (drag
/// right: the scene turns right), `pitch_rad` about the horizontal axis. The direction, the
/// centre (around the pivot) and up rotate together, and up becomes the rotated `screen_up`, so
/// it stays perpendicular to the direction and the camera can never become degenerate.
pub(crate) fn orbit(view: &View, pivot_world: DVec3, yaw_rad: f64, pitch_rad: f64) -> View {
    let Ok(basis) = view.validate() else {
        return *view;
    };
    if !(yaw_rad.is_finite() && pitch_rad.is_finite() && pivot_world.is_finite()) {
        return *view;
    }
    let rotation = DQuat::from_axis_angle(basis.screen_up, -yaw_rad)
        * DQuat::from_axis_angle(basis.horizontal, pitch_rad);
    let direction = rotation * basis.direction;
    let up = rotation * basis.screen_up;
    let center = pivot_world + rotation * (view.center_world - pivot_world);
    // Keep the length of the file's direction vector: only its orientation is the user's edit.
    let direction_length = view.direction_world.length();
    let candidate = View {
        direction_world: direction * direction_length,
        up_world: up,
        ..with_center(view, center)
    };
    if candidate.validate().is_ok() {
        candidate
    } else {
        *view
    }
}

/// Fits the centre and size so that every sphere is on screen with [`FRAME_ALL_MARGIN`] around
/// it, keeping the direction, up, image size and depth range. The centre moves only in the
/// screen plane, so t values stay as they were. A scene without spheres frames its extent box
/// (see [`scene_extent`]).
pub fn frame_all(scene: &Scene, view: &View) -> View {
    let Ok(basis) = view.validate() else {
        return *view;
    };
    let mut low = DVec2::splat(f64::INFINITY);
    let mut high = DVec2::splat(f64::NEG_INFINITY);
    if scene.spheres.is_empty() {
        let extent = scene_extent(scene);
        let radius = 0.5 * extent.diagonal();
        let center = basis.to_camera(extent.center() - view.center_world);
        low = DVec2::new(center.x, center.y) - radius;
        high = DVec2::new(center.x, center.y) + radius;
    }
    for sphere in &scene.spheres {
        let center = basis.to_camera(sphere.center_world - view.center_world);
        let center = DVec2::new(center.x, center.y);
        low = low.min(center - sphere.radius_world);
        high = high.max(center + sphere.radius_world);
    }
    let box_size = high - low;
    if !box_size.is_finite() {
        return *view;
    }
    let middle = 0.5 * (low + high);
    // `size` spans the longer image side; the shorter one sees `size · shorter / longer`.
    let (width, height) = (f64::from(view.width_px), f64::from(view.height_px));
    let longer = width.max(height);
    let needed = (box_size.x * longer / width).max(box_size.y * longer / height);
    // A NaN (zero-sized image) becomes the smallest size, as `max` would make it.
    let size_world = match needed / (1.0 - 2.0 * FRAME_ALL_MARGIN) {
        size if size.is_nan() => f64::MIN_POSITIVE,
        size => size.clamp(MIN_VIEW_SIZE, MAX_MAGNITUDE),
    };
    let center = view.center_world + middle.x * basis.horizontal + middle.y * basis.screen_up;
    View {
        size_world,
        ..with_center(view, center)
    }
}

/// The point orbiting turns around: the centre of the scene's extent.
pub fn orbit_pivot(scene: &Scene) -> DVec3 {
    scene_extent(scene).center()
}

/// `view` with centre `center` if that centre is usable, else `view` unchanged.
fn with_center(view: &View, center: DVec3) -> View {
    if center.is_finite() && center.abs().max_element() <= MAX_MAGNITUDE {
        View {
            center_world: center,
            ..*view
        }
    } else {
        *view
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::camera::CameraBasis;

    /// The camera basis of a view, if it has one.
    fn basis_of(view: &View) -> Option<CameraBasis> {
        view.validate().ok()
    }
    use crate::render::depth_map::DepthRange;
    use crate::render::render;
    use crate::scene::parse_scene;

    fn scene() -> Scene {
        parse_scene(include_str!("../../scenes/scene1_02.txt")).unwrap()
    }

    fn view(scene: &Scene) -> View {
        View::of_camera(&scene.camera, 200, 100, DepthRange::new(8.0, 12.0))
    }

    /// Screen (u, v) of a world point in a view.
    fn screen_of(view: &View, world: DVec3) -> DVec2 {
        let basis = view.validate().unwrap();
        let camera = basis.to_camera(world - view.center_world);
        DVec2::new(camera.x, camera.y)
    }

    #[test]
    fn pan_moves_the_picture_with_the_drag() {
        let scene = scene();
        let before = view(&scene);
        let after = pan(&before, DVec2::new(10.0, -4.0));
        // Rendering the panned view equals the old frame shifted by the drag.
        let old = render(&scene, &before).unwrap();
        let new = render(&scene, &after).unwrap();
        for y in 10..90 {
            for x in 20..180 {
                let moved = new.index(x + 10, y - 4);
                assert_eq!(new.colour[moved], old.colour[old.index(x, y)], "({x}, {y})");
            }
        }
        // The centre moved in the screen plane only: t is unchanged.
        let basis = before.validate().unwrap();
        let step = after.center_world - before.center_world;
        assert!(step.dot(basis.direction).abs() < 1e-12);
        assert!(step.length() > 0.0);
    }

    #[test]
    fn zoom_keeps_the_point_under_the_cursor() {
        let scene = scene();
        let before = view(&scene);
        let anchor_px = DVec2::new(150.0, 30.0);
        let grid = before.grid();
        let (u, v) = grid.screen_of_pixel_point(anchor_px.x, anchor_px.y);
        let basis = before.validate().unwrap();
        let world = before.center_world + u * basis.horizontal + v * basis.screen_up;
        for factor in [0.5, 0.9, 1.25, 3.0] {
            let after = zoom_at(&before, factor, anchor_px);
            assert!((after.size_world - before.size_world * factor).abs() < 1e-12);
            let (u2, v2) = after.grid().screen_of_pixel_point(anchor_px.x, anchor_px.y);
            let on_screen = screen_of(&after, world);
            assert!(
                (on_screen - DVec2::new(u2, v2)).length() < 1e-12,
                "{factor}"
            );
        }
        // Hostile factors leave the view as it was.
        for factor in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(zoom_at(&before, factor, anchor_px), before);
        }
    }

    #[test]
    fn orbit_turns_direction_and_centre_around_the_pivot() {
        let scene = scene();
        let before = view(&scene);
        let pivot = orbit_pivot(&scene);
        let after = orbit(&before, pivot, 0.3, -0.2);
        let basis = after.validate().unwrap();
        // Distance to the pivot is kept; up is perpendicular to the new direction.
        let distance = |v: &View| (v.center_world - pivot).length();
        assert!((distance(&after) - distance(&before)).abs() < 1e-9);
        assert!(after.up_world.dot(basis.direction).abs() < 1e-12);
        let old = before.direction_world.normalize();
        let angle = old.angle_between(basis.direction);
        assert!(angle > 0.25 && angle < 0.5, "{angle}");
        // A full turn about the screen's up axis comes back.
        let mut turned = before;
        for _ in 0..8 {
            turned = orbit(&turned, pivot, std::f64::consts::FRAC_PI_4, 0.0);
        }
        assert!((turned.center_world - before.center_world).length() < 1e-9);
        // Yawing right turns the scene right, its near side following the drag: a point right of
        // the pivot turns away from the camera.
        let right_point = pivot + basis_of(&before).unwrap().horizontal;
        let t = |v: &View, p: DVec3| (p - v.center_world).dot(v.direction_world.normalize());
        let yawed = orbit(&before, pivot, 0.2, 0.0);
        assert!(t(&yawed, right_point) > t(&before, right_point));
    }

    #[test]
    fn frame_all_shows_every_sphere_with_a_margin() {
        let scene = scene();
        let mut far = view(&scene);
        far.center_world += DVec3::new(30.0, -20.0, 0.0);
        far.size_world = 0.1;
        let framed = frame_all(&scene, &far);
        let basis = framed.validate().unwrap();
        // t is unchanged: the centre moved in the screen plane.
        let step = framed.center_world - far.center_world;
        assert!(step.dot(basis.direction).abs() < 1e-9);
        let half_width = 0.5 * framed.size_world;
        let half_height = half_width * f64::from(framed.height_px) / f64::from(framed.width_px);
        let mut touches = false;
        for sphere in &scene.spheres {
            let c = screen_of(&framed, sphere.center_world);
            let r = sphere.radius_world;
            assert!(c.x.abs() + r <= half_width * (1.0 - 2.0 * FRAME_ALL_MARGIN) + 1e-9);
            assert!(c.y.abs() + r <= half_height * (1.0 - 2.0 * FRAME_ALL_MARGIN) + 1e-9);
            touches |= (c.y.abs() + r - half_height * 0.9).abs() < 1e-6
                || (c.x.abs() + r - half_width * 0.9).abs() < 1e-6;
        }
        assert!(touches, "the scene fills the screen up to the margin");
    }

    #[test]
    fn unusable_views_are_returned_unchanged() {
        let scene = scene();
        let mut broken = view(&scene);
        broken.size_world = f64::NAN;
        assert!(pan(&broken, DVec2::ONE).size_world.is_nan());
        let mut parallel = view(&scene);
        parallel.up_world = parallel.direction_world;
        assert_eq!(orbit(&parallel, DVec3::ZERO, 0.1, 0.1), parallel);
        assert_eq!(frame_all(&scene, &parallel), parallel);
        let good = view(&scene);
        assert_eq!(pan(&good, DVec2::new(f64::NAN, 0.0)), good);
        for factor in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(zoom_at(&good, factor, DVec2::ONE), good, "{factor}");
        }
        assert_eq!(zoom_at(&good, 2.0, DVec2::splat(f64::NAN)), good);
        assert_eq!(orbit(&good, DVec3::splat(f64::NAN), 0.1, 0.0), good);
        assert_eq!(orbit(&good, DVec3::ZERO, f64::INFINITY, 0.0), good);
        // Extreme factors stop at the edges of the accepted sizes.
        let huge = zoom_at(&good, 1e300, DVec2::ONE);
        assert!(huge.size_world <= MAX_MAGNITUDE && huge.validate().is_ok());
        let tiny = zoom_at(&good, 1e-300, DVec2::ONE);
        assert!(tiny.size_world > 0.0 && tiny.validate().is_ok());
    }
}
