//! The build script: the commit the program is built from (for `raytracer --version` and the
//! viewer's help overlay), and on Windows the program's icon and version information in its
//! properties.
//!
//! The commit is `RAYTRACER_COMMIT` where the builder sets it (a release workflow builds from a
//! tag), else what `git` says of the checkout, with `+changes` where tracked files differ from
//! it, else `unknown` (a build from a source archive, without git).

use std::path::Path;
use std::process::Command;

fn main() {
    println!("cargo:rustc-env=RAYTRACER_COMMIT={}", commit());
    println!("cargo:rerun-if-env-changed=RAYTRACER_COMMIT");
    // A new commit, a change staged or committed, and any source file: each can change the
    // answer. (Without these lines cargo reruns the script on any change in the package, which
    // misses new commits.)
    for path in ["build.rs", "Cargo.toml", "src", "assets", "scenes", "web"] {
        println!("cargo:rerun-if-changed={path}");
    }
    if let Some(git) = git_dir() {
        for file in ["HEAD", "index", "packed-refs"] {
            println!("cargo:rerun-if-changed={}", git.join(file).display());
        }
        if let Ok(head) = std::fs::read_to_string(git.join("HEAD"))
            && let Some(reference) = head.trim().strip_prefix("ref: ")
        {
            println!("cargo:rerun-if-changed={}", git.join(reference).display());
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
    // Tracked files only: the build's own outputs and a user's scratch files are not the source.
    let changed = git(&["status", "--porcelain", "--untracked-files=no"])
        .is_some_and(|status| !status.trim().is_empty());
    if changed {
        format!("{hash}+changes")
    } else {
        hash
    }
}

/// The checkout's git folder, where there is one.
fn git_dir() -> Option<std::path::PathBuf> {
    let dir = git(&["rev-parse", "--absolute-git-dir"])?;
    let dir = Path::new(dir.trim()).to_path_buf();
    dir.is_dir().then_some(dir)
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
