//! A real X server for the tests that run the real viewer window: Xvfb on a free display, and
//! screenshots of it. Needs `Xvfb` and ImageMagick's `import` (scripts/test.sh installs them).

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use image::RgbImage;

/// A child process killed (and reaped) when dropped.
pub(crate) struct KillOnDrop(pub(crate) Child);

impl Drop for KillOnDrop {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// Starts Xvfb on a free display (1280×800); returns it and the display name.
pub(crate) fn start_xvfb() -> (KillOnDrop, String) {
    for number in 90..140 {
        if Path::new(&format!("/tmp/.X{number}-lock")).exists() {
            continue;
        }
        let display = format!(":{number}");
        let child = Command::new("Xvfb")
            .args([
                display.as_str(),
                "-screen",
                "0",
                "1280x800x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("Xvfb is needed for this test (scripts/test.sh installs it)");
        let mut xvfb = KillOnDrop(child);
        let deadline = Instant::now() + Duration::from_secs(10);
        while Instant::now() < deadline {
            if Path::new(&format!("/tmp/.X11-unix/X{number}")).exists() {
                return (xvfb, display);
            }
            if let Ok(Some(_)) = xvfb.0.try_wait() {
                break; // display taken meanwhile: try the next
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    }
    panic!("could not start Xvfb on any display :90..:139");
}

/// A screenshot of the whole X screen (ImageMagick's `import`).
pub(crate) fn screenshot(display: &str, path: &Path) -> Option<RgbImage> {
    let status = Command::new("import")
        .args(["-display", display, "-window", "root"])
        .arg(path)
        .stderr(Stdio::null())
        .status()
        .expect("ImageMagick's import is needed for this test (scripts/test.sh installs it)");
    if !status.success() {
        return None;
    }
    image::open(path).ok().map(|i| i.to_rgb8())
}

/// The viewer binary on `display`, with a fresh home under `home` (its settings go to
/// `home/data`), its standard error piped.
pub(crate) fn viewer_command(display: &str, home: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raytracer"));
    command
        .env("DISPLAY", display)
        .env_remove("WAYLAND_DISPLAY")
        .env("HOME", home)
        .env("XDG_DATA_HOME", home.join("data"))
        .env("XDG_CONFIG_HOME", home.join("config"))
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    command
}
