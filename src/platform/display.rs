//! Whether a window and file dialogs can be opened: on Linux the viewer talks to an X or Wayland
//! server named by the environment, and its file dialogs go through a desktop portal on the
//! session bus (or zenity); Windows and macOS always have their own display and dialogs.

/// Whether the environment names no display server to open a window on (`DISPLAY`,
/// `WAYLAND_DISPLAY` and `WAYLAND_SOCKET` all unset or empty). Always `false` on Windows and
/// macOS.
pub fn display_server_missing() -> bool {
    if cfg!(any(windows, target_os = "macos")) {
        return false;
    }
    let set = |name| std::env::var_os(name).is_some_and(|value| !value.is_empty());
    !(set("DISPLAY") || set("WAYLAND_DISPLAY") || set("WAYLAND_SOCKET"))
}

/// Whether native file dialogs here need a desktop portal or zenity (Linux and the other Unix
/// desktops); `false` on Windows and macOS, whose dialogs are the system's own.
pub fn dialogs_need_a_desktop_portal() -> bool {
    // A browser page has the browser's own file chooser.
    !cfg!(any(windows, target_os = "macos", target_arch = "wasm32"))
}
