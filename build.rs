//! The build script: the commit the program is built from (for `raytracer --version` and the
//! viewer's help overlay), and on Windows the program's icon and version information in its
//! properties.
//!
//! The commit is `RAYTRACER_COMMIT` where the builder sets it, else what `git` says of the
//! checkout, with `+changes` where tracked source files differ from it, else `unknown` (a build
//! from a source archive, without git).

use std::path::Path;
use std::process::Command;

/// The source paths whose change can change the build (and the `+changes` mark).
const SOURCES: [&str; 7] = [
    "build.rs",
    "Cargo.toml",
    "Cargo.lock",
    "src",
    "assets",
    "scenes",
    "web",
];

fn main() {
    println!("cargo:rustc-env=RAYTRACER_COMMIT={}", commit());
    println!("cargo:rerun-if-env-changed=RAYTRACER_COMMIT");
    // A new commit, a change staged or committed, and any source file: each can change the
    // answer. (Without these lines cargo reruns the script on any change in the package, which
    // misses new commits.) Only paths that exist: cargo reruns the script on every build for a
    // path that does not (a checkout without packed refs).
    let mut watched: Vec<std::path::PathBuf> =
        SOURCES.iter().map(std::path::PathBuf::from).collect();
    for name in ["HEAD", "index", "packed-refs"] {
        if let Some(path) = git(&["rev-parse", "--git-path", name]) {
            watched.push(path.into());
        }
    }
    if let Some(reference) = git(&["symbolic-ref", "-q", "HEAD"])
        && let Some(path) = git(&["rev-parse", "--git-path", &reference])
    {
        watched.push(path.into());
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for path in watched {
        if root.join(&path).exists() {
            println!("cargo:rerun-if-changed={}", path.display());
        }
    }
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("windows") {
        windows_resources();
    }
}

/// The commit, as `--version` prints it.
fn commit() -> String {
    if let Ok(given) = std::env::var("RAYTRACER_COMMIT")
        && !given.trim().is_empty()
    {
        return given.trim().to_owned();
    }
    let Some(hash) = git(&["rev-parse", "--short=12", "HEAD"]) else {
        return "unknown".to_owned();
    };
    // Tracked source files only: the build's own outputs, the docs and a user's scratch files do
    // not change the program (and a change there would not rerun this script).
    let mut status = vec![
        "--no-optional-locks",
        "status",
        "--porcelain",
        "--untracked-files=no",
        "--",
    ];
    status.extend(SOURCES);
    let changed = git(&status).is_some_and(|status| !status.trim().is_empty());
    if changed {
        format!("{hash}+changes")
    } else {
        hash
    }
}

/// One git command's output in the package's folder, `None` where git is missing or fails.
fn git(arguments: &[&str]) -> Option<String> {
    let output = Command::new("git")
        .args(arguments)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()?;
    let text = String::from_utf8(output.stdout).ok()?;
    (output.status.success() && !text.trim().is_empty()).then(|| text.trim().to_owned())
}

/// The Windows program's icon (`assets/raytracer.ico`: three overlapping flat discs, made with
/// ImageMagick by `convert -size 256x256 xc:none -fill '#1d2230' -draw "roundrectangle 8,8
/// 247,247 40,40" -fill '#e0483e' -draw "circle 100,150 100,78" -fill '#3fa34d' -draw "circle
/// 160,160 160,110" -fill '#3a6fd8' -draw "circle 150,95 150,55" -depth 8 -define
/// icon:auto-resize=256,64,48,32,16 assets/raytracer.ico`) and version information (name,
/// description, version and licence from Cargo.toml), compiled by the resource compiler of the
/// toolchain (mingw-w64's `windres` when cross-compiling, `rc.exe` with MSVC).
fn windows_resources() {
    println!("cargo:rerun-if-changed=assets/raytracer.ico");
    let mut resource = winresource::WindowsResource::new();
    resource
        .set_icon("assets/raytracer.ico")
        .set("ProductName", "raytracer")
        .set(
            "FileDescription",
            "raytracer: a ray-casting viewer for the 6.837 scene format",
        )
        .set("LegalCopyright", "MIT OR Apache-2.0")
        .set("Comments", &format!("commit {}", commit()));
    if let Err(error) = resource.compile() {
        // No resource compiler is a broken toolchain for this target: say so and stop.
        panic!("the Windows resources (icon, version information) could not be compiled: {error}");
    }
}
