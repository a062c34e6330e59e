//! What durability costs the command line: writing the two 12 MB images of a 2000×2000 render
//! (each to a temporary file beside the destination, then renamed over it, as the program writes
//! them) with and without syncing each file to disk before the rename. Medians of interleaved
//! rounds, in a temporary folder on the disk the program is run from. Run by
//! `scripts/command-vs-cpp.sh`, which puts the table in `docs/command-vs-cpp.md`:
//!
//! ```sh
//! cargo run --release --example write_cost -- [ROUNDS]
//! ```

use std::io::Write;
use std::path::Path;
use std::time::Instant;

/// Bytes of one 2000×2000 24-bit TGA.
const IMAGE_BYTES: usize = 18 + 2000 * 2000 * 3;

fn write_both(folder: &Path, bytes: &[u8], sync: bool) -> f64 {
    let started = Instant::now();
    for name in ["colour.tga", "depth.tga"] {
        let temporary = folder.join(format!(".{name}.tmp"));
        let mut file = std::fs::File::create(&temporary).expect("creates");
        file.write_all(bytes).expect("writes");
        if sync {
            file.sync_all().expect("syncs");
        }
        drop(file);
        std::fs::rename(&temporary, folder.join(name)).expect("renames");
    }
    started.elapsed().as_secs_f64() * 1e3
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|r| r.parse().ok())
        .unwrap_or(21);
    let folder = tempfile::tempdir_in(".").expect("a temporary folder here");
    // Not all one value, so no layer can store it as a hole.
    let bytes: Vec<u8> = (0..IMAGE_BYTES).map(|i| (i * 7 % 251) as u8).collect();
    let (mut synced, mut unsynced) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        synced.push(write_both(folder.path(), &bytes, true));
        unsynced.push(write_both(folder.path(), &bytes, false));
    }
    let (synced, unsynced) = (median(synced), median(unsynced));
    println!("| writing both images | ms |");
    println!("|---|---|");
    println!("| synced to disk before the rename (what the program does) | {synced:.1} |");
    println!("| not synced | {unsynced:.1} |");
    println!("| **cost of durability** | **{:.1}** |", synced - unsynced);
}
