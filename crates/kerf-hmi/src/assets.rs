//! The operator screen's files, embedded in the binary so the page works
//! with no network and no files beside the executable. three.js is the
//! npm package's own build, copied into web/vendor by web/vendor.mjs.

/// One embedded file.
pub struct Asset {
    /// Path under `/assets/` (or `index.html` for `/`).
    pub path: &'static str,
    /// Content type.
    pub mime: &'static str,
    /// Bytes.
    pub bytes: &'static [u8],
}

macro_rules! asset {
    ($path:literal, $mime:expr) => {
        Asset {
            path: $path,
            mime: $mime,
            bytes: include_bytes!(concat!("../web/", $path)),
        }
    };
}

const JS: &str = "text/javascript; charset=utf-8";

/// Every embedded file.
pub static ASSETS: &[Asset] = &[
    asset!("index.html", "text/html; charset=utf-8"),
    asset!("style.css", "text/css; charset=utf-8"),
    asset!("app.js", JS),
    asset!("screens.js", JS),
    asset!("graph.js", JS),
    asset!("lines.js", JS),
    asset!("coarse.js", JS),
    asset!("lod.js", JS),
    asset!("grid.js", JS),
    asset!("vendor/three.module.js", JS),
    asset!("vendor/three.core.js", JS),
    asset!("vendor/OrbitControls.js", JS),
    asset!("vendor/three.LICENSE", "text/plain; charset=utf-8"),
];

/// The file at `path`, if embedded.
pub fn get(path: &str) -> Option<&'static Asset> {
    ASSETS.iter().find(|a| a.path == path)
}
