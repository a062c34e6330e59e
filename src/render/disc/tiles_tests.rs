//! Unit tests of `tiles` (a file of their own, so that the module stays short).

use super::*;
use crate::render::NO_HIT;
use crate::render::rng::SplitMix64;

/// Random discs over (and beyond) a `width`×`height` image of one world unit per pixel, from
/// a tenth of a pixel to twice the image across, with exact copies of some (ties everywhere
/// they reach) and some centred on pixel centres with whole radii (rims through pixel
/// centres).
fn random_discs(rng: &mut SplitMix64, count: u32, width: u32, height: u32) -> Vec<Disc> {
    let (half_width, half_height) = (f64::from(width) / 2.0, f64::from(height) / 2.0);
    let mut discs: Vec<Disc> = (0..count)
        .map(|sphere| {
            let mut radius = rng.log_uniform(0.1, 2.0 * f64::from(width.max(height)));
            let (mut u, mut v) = (
                rng.uniform(-half_width - 10.0, half_width + 10.0),
                rng.uniform(-half_height - 10.0, half_height + 10.0),
            );
            if sphere % 5 == 0 {
                // Pixel centres sit at half-integers when the side is even.
                u = u.round() + if width.is_multiple_of(2) { 0.5 } else { 0.0 };
                v = v.round() + if height.is_multiple_of(2) { 0.5 } else { 0.0 };
                radius = radius.round().max(1.0);
            }
            Disc {
                u,
                v,
                w: rng.uniform(-50.0, 50.0),
                radius_sq: radius * radius,
                sphere,
            }
        })
        .collect();
    let copies: Vec<Disc> = discs
        .iter()
        .step_by(7)
        .zip(count..)
        .map(|(disc, sphere)| Disc { sphere, ..*disc })
        .collect();
    discs.extend(copies);
    discs
}

/// What every pixel ends up with, worked out pixel by pixel: the nearest hit of all discs
/// over what `t` and `sphere` already hold, a tie to the sphere first in the file.
fn pixel_by_pixel(
    discs: &[Disc],
    grid: &PixelGrid,
    mut t: Vec<f64>,
    mut sphere: Vec<u32>,
) -> (Vec<f64>, Vec<u32>) {
    let (width, height) = (grid.width_px as usize, grid.height_px as usize);
    for row in 0..height {
        let v = grid.v_of_row((height - 1 - row) as f64);
        for x in 0..width {
            let u = grid.u_of_column(x as f64);
            let pixel = row * width + x;
            for disc in discs {
                if let Some(hit) = disc.hit_t(u, v)
                    && (hit < t[pixel] || (hit == t[pixel] && disc.sphere < sphere[pixel]))
                {
                    t[pixel] = hit;
                    sphere[pixel] = disc.sphere;
                }
            }
        }
    }
    (t, sphere)
}

#[test]
fn tiles_draw_what_the_discs_show_pixel_by_pixel_in_any_order() {
    // Widths that are and are not whole groups and tiles (partial groups go one pixel at a
    // time); discs front to back, back to front and in file order; over an empty image and
    // over one an earlier pass partly drew, some of it at exactly a disc's nearest t.
    let mut rng = SplitMix64::new(77);
    let mut covered = 0;
    for case in 0..120u32 {
        let (width, height) = (1 + (case * 13) % 67, 1 + (case * 5) % 29);
        let grid = PixelGrid::new(width, height, f64::from(width.max(height)));
        let mut discs = random_discs(&mut rng, 1 + case % 40, width, height);
        match case % 3 {
            0 => discs.sort_by(|a, b| a.front_t().total_cmp(&b.front_t())),
            1 => discs.sort_by(|a, b| b.front_t().total_cmp(&a.front_t())),
            _ => {}
        }
        let pixels = (width * height) as usize;
        let (mut t, mut sphere) = (vec![f64::INFINITY; pixels], vec![NO_HIT; pixels]);
        if case % 2 == 1 {
            for (pixel, disc) in (0..pixels).step_by(3).zip(discs.iter().cycle()) {
                t[pixel] = if pixel % 2 == 0 {
                    disc.front_t()
                } else {
                    rng.uniform(-60.0, 60.0)
                };
                sphere[pixel] = disc.sphere + 1;
            }
        }
        let wanted = pixel_by_pixel(&discs, &grid, t.clone(), sphere.clone());
        rasterise_discs_in_tiles(&discs, &grid, (&mut t, &mut sphere));
        for pixel in 0..pixels {
            assert_eq!(
                (t[pixel].to_bits(), sphere[pixel]),
                (wanted.0[pixel].to_bits(), wanted.1[pixel]),
                "case {case} ({width}×{height}), pixel {pixel}"
            );
        }
        covered += wanted.1.iter().filter(|&&s| s != NO_HIT).count();
    }
    assert!(covered > 20_000, "{covered}");
}

#[test]
fn a_disc_whose_nearest_t_only_ties_the_tile_still_takes_its_tie() {
    // One tile, drawn everywhere at t = 5 by sphere 10; a disc of sphere 3 centred on a pixel
    // centre reaches t = 5 there and only there (w − r = 7 − 2). Its nearest t is no nearer
    // than the tile's farthest, yet it must be drawn: it wins that pixel's tie.
    let grid = PixelGrid::new(8, 8, 8.0);
    let (mut t, mut sphere) = (vec![5.0; 64], vec![10; 64]);
    let disc = Disc {
        u: grid.u_of_column(3.0),
        v: grid.v_of_row(4.0),
        w: 7.0,
        radius_sq: 4.0,
        sphere: 3,
    };
    rasterise_discs_in_tiles(&[disc], &grid, (&mut t, &mut sphere));
    let centre = (8 - 1 - 4) * 8 + 3;
    assert_eq!((t[centre], sphere[centre]), (5.0, 3));
    assert_eq!(sphere.iter().filter(|&&s| s == 3).count(), 1);
    // A tie between zeros of both signs: the winner's own t, −0, as the pixel-by-pixel
    // rule gives it (w = −0, and on the rim two pixels right of the centre √0 = 0).
    let (mut t, mut sphere) = (vec![0.0; 64], vec![10; 64]);
    let disc = Disc { w: -0.0, ..disc };
    rasterise_discs_in_tiles(&[disc], &grid, (&mut t, &mut sphere));
    let rim = centre + 2;
    assert_eq!((t[rim].to_bits(), sphere[rim]), ((-0.0f64).to_bits(), 3));
}

#[test]
fn hidden_discs_cost_no_pixel_tests() {
    // Forty layers of discs, each layer covering the image: drawn front to back, the layers
    // behind the first are hidden and tested nowhere (the tiles stop, and what is left of a
    // disc is skipped four pixels at a time); back to front, every layer is drawn. The
    // picture is the same either way.
    let grid = PixelGrid::new(64, 64, 64.0);
    let discs: Vec<Disc> = (0..40u32)
        .flat_map(|layer| {
            (0..16u32).map(move |cell| Disc {
                u: -24.0 + 16.0 * f64::from(cell % 4),
                v: -24.0 + 16.0 * f64::from(cell / 4),
                w: 100.0 * f64::from(layer),
                radius_sq: 12.0 * 12.0,
                sphere: layer * 16 + cell,
            })
        })
        .collect();
    let draw = |discs: &[Disc]| {
        let (mut t, mut sphere) = (vec![f64::INFINITY; 64 * 64], vec![NO_HIT; 64 * 64]);
        let tests = rasterise_discs_in_tiles(discs, &grid, (&mut t, &mut sphere));
        (tests, sphere)
    };
    let (front_to_back_tests, front_to_back) = draw(&discs);
    let reversed: Vec<Disc> = discs.iter().rev().copied().collect();
    let (back_to_front_tests, back_to_front) = draw(&reversed);
    assert_eq!(front_to_back, back_to_front);
    assert!(
        front_to_back.iter().all(|&s| s < 16),
        "the first layer shows"
    );
    assert!(
        front_to_back_tests * 10 < back_to_front_tests,
        "{front_to_back_tests} against {back_to_front_tests}"
    );
}
