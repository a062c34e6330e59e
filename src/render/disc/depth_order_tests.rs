//! Unit tests of `depth_order` (a file of their own, so that the module stays short).

use super::*;
use crate::render::rng::SplitMix64;

/// The pixels (row-major, top row first) whose centres `disc` covers, found pixel by pixel
/// within its bounding square and two pixels more.
fn covered(disc: &Disc, grid: &PixelGrid) -> Vec<usize> {
    let (width, height) = (grid.width_px as usize, grid.height_px as usize);
    let reach = disc.radius_sq.sqrt() / grid.pixel_size_world + 2.0;
    let column = disc.u / grid.pixel_size_world + width as f64 / 2.0;
    let row = height as f64 / 2.0 - disc.v / grid.pixel_size_world;
    let clamp = |at: f64, count: usize| at.clamp(0.0, count as f64) as usize;
    let rows = clamp(row - reach, height)..clamp(row + reach + 1.0, height);
    let columns = clamp(column - reach, width)..clamp(column + reach + 1.0, width);
    rows.flat_map(|row| columns.clone().map(move |x| (row, x)))
        .filter(|&(row, x)| {
            let u = grid.u_of_column(x as f64);
            let v = grid.v_of_row((height - 1 - row) as f64);
            disc.hit_t(u, v).is_some()
        })
        .map(|(row, x)| row * width + x)
        .collect()
}

/// The t of `disc` at `pixel`.
fn t_at(disc: &Disc, pixel: usize, grid: &PixelGrid) -> Option<f64> {
    let (width, height) = (grid.width_px as usize, grid.height_px as usize);
    let u = grid.u_of_column((pixel % width) as f64);
    let v = grid.v_of_row((height - 1 - pixel / width) as f64);
    disc.hit_t(u, v)
}

/// Splits `discs` into passes, takes every pass against the coarse depth of `t`, and checks
/// that every disc as near as a pixel's t somewhere (found pixel by pixel) is kept, and that
/// some are not.
fn assert_keeps_what_can_change(discs: &[Disc], t: &[f64], grid: &PixelGrid) {
    let fronts = discs.iter().map(Disc::front_t);
    let nearest = fronts.clone().fold(f64::INFINITY, f64::min);
    let farthest = fronts.fold(f64::NEG_INFINITY, f64::max);
    let mut passes = Passes::of(discs, grid, 1.0, nearest, farthest - nearest);
    assert!(passes.count() > 2, "several passes");
    let coarse = CoarseDepth::of(t, grid);
    let kept: Vec<u32> = (0..passes.count())
        .flat_map(|pass| passes.take(pass, Some(&coarse), grid))
        .flat_map(|part| part.placed)
        .map(|placed| placed.disc.sphere)
        .collect();
    let size = (grid.width_px, grid.height_px);
    let mut wanted = 0;
    for disc in discs {
        let can_change = covered(disc, grid)
            .into_iter()
            .any(|pixel| t_at(disc, pixel, grid).is_some_and(|hit| hit <= t[pixel]));
        if can_change {
            wanted += 1;
            assert!(
                kept.contains(&disc.sphere),
                "disc {} dropped {size:?}",
                disc.sphere
            );
        }
    }
    assert!(
        wanted > 0 && kept.len() < discs.len(),
        "{wanted} {} {size:?}",
        kept.len()
    );
}

fn random_discs(rng: &mut SplitMix64, count: u32, grid: &PixelGrid) -> Vec<Disc> {
    let (half_width, half_height) = (
        f64::from(grid.width_px) / 2.0,
        f64::from(grid.height_px) / 2.0,
    );
    (0..count)
        .map(|sphere| {
            let radius = rng.log_uniform(0.05, 40.0);
            Disc {
                u: rng.uniform(-half_width - 20.0, half_width + 20.0),
                v: rng.uniform(-half_height - 20.0, half_height + 20.0),
                w: rng.uniform(2.0, 60.0),
                radius_sq: radius * radius,
                sphere,
            }
        })
        .collect()
}

#[test]
fn passes_keep_every_disc_seen_through_a_few_gaps() {
    // What earlier passes drew is near everywhere but at a few pixels, uncovered or at
    // exactly the t a disc has there (a tie it may win): most screen cells lie wholly behind,
    // so whole groups are dropped, and a disc may change only the pixels near the gaps.
    let mut rng = SplitMix64::new(21);
    for (width, height) in [(1, 1), (37, 23), (128, 5), (5, 128), (64, 64)] {
        let grid = PixelGrid::new(width, height, f64::from(width.max(height)));
        let mut discs = random_discs(&mut rng, 2_000, &grid);
        let mut t = vec![1.0; (width * height) as usize];
        let pixels = t.len();
        for _ in 0..6 {
            t[(rng.uniform(0.0, 1.0) * pixels as f64) as usize % pixels] = f64::INFINITY;
        }
        for disc in discs.iter().step_by(400) {
            let pixel = (rng.uniform(0.0, 1.0) * pixels as f64) as usize % pixels;
            if let Some(hit) = t_at(disc, pixel, &grid) {
                t[pixel] = hit;
            }
        }
        // Discs centred on a pixel, which holds exactly their nearest t: the tile's farthest
        // t equals it, a tie they may win.
        for disc in discs.iter_mut().skip(3).step_by(300) {
            let pixel = (rng.uniform(0.0, 1.0) * pixels as f64) as usize % pixels;
            let (x, row) = (pixel % width as usize, pixel / width as usize);
            disc.u = grid.u_of_column(x as f64);
            disc.v = grid.v_of_row((height as usize - 1 - row) as f64);
            t[pixel] = disc.front_t();
        }
        assert_keeps_what_can_change(&discs, &t, &grid);
    }
}

#[test]
fn passes_keep_every_disc_that_barely_reaches_a_gap() {
    // Gaps at the covered pixel of a disc farthest from its centre, left or right: a disc
    // is kept only if its extent is known to the pixel.
    let mut rng = SplitMix64::new(22);
    let grid = PixelGrid::new(400, 300, 400.0);
    let discs = random_discs(&mut rng, 3_000, &grid);
    let mut t = vec![1.0; 400 * 300];
    for (index, disc) in discs.iter().enumerate().step_by(20) {
        let column_off = |pixel: &usize| grid.u_of_column((pixel % 400) as f64) - disc.u;
        let pixels = covered(disc, &grid);
        let rim = if index % 40 == 0 {
            pixels
                .into_iter()
                .min_by(|a, b| column_off(a).total_cmp(&column_off(b)))
        } else {
            pixels
                .into_iter()
                .max_by(|a, b| column_off(a).total_cmp(&column_off(b)))
        };
        if let Some(pixel) = rim {
            t[pixel] = f64::INFINITY;
        }
    }
    assert_keeps_what_can_change(&discs, &t, &grid);
}
