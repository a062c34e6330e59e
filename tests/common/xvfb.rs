//! A real X server for the tests that run the real viewer window: Xvfb on a free display, and
//! screenshots of it. Needs `Xvfb` and ImageMagick's `import` (cargo xtask test installs them).

use std::io::{BufRead, BufReader, Read};
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
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

impl KillOnDrop {
    /// Waits for the process to end, at most `within`; fails with `late` if it has not by then.
    pub(crate) fn wait_within(&mut self, within: Duration, late: &str) -> ExitStatus {
        let deadline = Instant::now() + within;
        loop {
            if let Some(status) = self.0.try_wait().unwrap() {
                return status;
            }
            assert!(Instant::now() < deadline, "{late}");
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// What the process wrote to its piped standard error (read to the end).
    pub(crate) fn stderr_text(&mut self) -> String {
        let mut text = String::new();
        if let Some(mut pipe) = self.0.stderr.take() {
            let _ = pipe.read_to_string(&mut text);
        }
        text
    }
}

/// Starts Xvfb on a free display (1280×800); returns it and the display name. Xvfb picks the
/// display itself and names it once it accepts connections (`-displayfd`), so tests running at
/// once never share one.
pub(crate) fn start_xvfb() -> (KillOnDrop, String) {
    let child = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "1280x800x24",
            "-nolisten",
            "tcp",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("Xvfb is needed for this test (cargo xtask test installs it)");
    let mut xvfb = KillOnDrop(child);
    // Read on a thread, so that an Xvfb that hangs fails the test after 10 s (and is killed).
    let (sender, named) = std::sync::mpsc::channel();
    if let Some(stdout) = xvfb.0.stdout.take() {
        std::thread::spawn(move || {
            let mut number = String::new();
            let _ = BufReader::new(stdout).read_line(&mut number);
            let _ = sender.send(number);
        });
    }
    let number = named
        .recv_timeout(Duration::from_secs(10))
        .unwrap_or_default();
    let number = number.trim();
    assert!(
        !number.is_empty() && number.bytes().all(|b| b.is_ascii_digit()),
        "Xvfb did not start within 10 s (it named no display)"
    );
    (xvfb, format!(":{number}"))
}

/// A screenshot of the whole X screen (ImageMagick's `import`).
pub(crate) fn screenshot(display: &str, path: &Path) -> Option<RgbImage> {
    let status = Command::new("import")
        .args(["-display", display, "-window", "root"])
        .arg(path)
        .stderr(Stdio::null())
        .status()
        .expect("ImageMagick's import is needed for this test (cargo xtask test installs it)");
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
        .env_remove("RAYTRACER_RENDERER")
        .env_remove("RAYTRACER_FRAME_LOG")
        .env("HOME", home)
        .env("XDG_DATA_HOME", home.join("data"))
        .env("XDG_CONFIG_HOME", home.join("config"))
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    command
}
