//! The minimum supported Rust version, checked without a second toolchain.
//!
//! The workspace states one `rust-version`; the README names it as the
//! oldest toolchain that builds and tests kerf. Two things can make that
//! untrue: a crate of ours that does not inherit it, or a locked dependency
//! that itself needs a newer compiler (the usual way an MSRV silently rises).
//! This test reads `cargo metadata` for the locked graph and checks both,
//! and that the README says the same version. Newer *standard library* APIs
//! in our own code are caught by clippy's `incompatible_msrv` lint, which
//! reads the same `rust-version` and runs in CI with `-D warnings`.

use std::path::Path;
use std::process::Command;

/// A dotted version such as `1.88` or `1.88.0`, compared part by part.
fn parse_version(text: &str) -> Vec<u32> {
    text.split('.')
        .map(|part| part.parse().expect("a numeric version part"))
        .collect()
}

fn workspace_root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .and_then(Path::parent)
        .expect("crates/kerf-cli sits two levels below the workspace")
}

/// The `rust-version` line of the workspace's `[workspace.package]`.
fn workspace_rust_version() -> String {
    let manifest = std::fs::read_to_string(workspace_root().join("Cargo.toml")).unwrap();
    let table: toml::Table = manifest.parse().unwrap();
    table["workspace"]["package"]["rust-version"]
        .as_str()
        .expect("workspace.package.rust-version is a string")
        .to_string()
}

/// The host's target triple (`rustc -vV`'s `host:` line).
fn host_triple() -> String {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_string());
    let output = Command::new(rustc)
        .arg("-vV")
        .output()
        .expect("rustc -vV runs");
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .expect("rustc -vV names the host")
        .to_string()
}

/// The locked graph for the host. Offline, cargo has only the packages a
/// build here downloaded: those of other platforms (Windows console
/// crates, say) are not on a fresh machine, so the graph is the host's.
fn locked_metadata() -> serde_json::Value {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let host = host_triple();
    let output = Command::new(cargo)
        .args(["metadata", "--format-version", "1", "--locked", "--offline"])
        .args(["--filter-platform", &host])
        .current_dir(workspace_root())
        .output()
        .expect("cargo metadata runs");
    assert!(
        output.status.success(),
        "cargo metadata failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("cargo metadata prints JSON")
}

#[test]
fn no_locked_dependency_needs_a_newer_compiler_than_the_stated_minimum() {
    let msrv = workspace_rust_version();
    let ceiling = parse_version(&msrv);
    let metadata = locked_metadata();
    let members: Vec<&str> = metadata["workspace_members"]
        .as_array()
        .unwrap()
        .iter()
        .map(|id| id.as_str().unwrap())
        .collect();
    let mut too_new = Vec::new();
    let mut checked = 0;
    for package in metadata["packages"].as_array().unwrap() {
        let name = package["name"].as_str().unwrap();
        let id = package["id"].as_str().unwrap();
        let stated = package["rust_version"].as_str();
        if members.contains(&id) {
            assert_eq!(
                stated,
                Some(msrv.as_str()),
                "workspace crate {name} must inherit rust-version {msrv}"
            );
        }
        if let Some(version) = stated {
            checked += 1;
            if parse_version(version) > ceiling {
                too_new.push(format!("{name} {} needs {version}", package["version"]));
            }
        }
    }
    assert!(
        members.len() >= 9,
        "expected every kerf crate in the workspace"
    );
    assert!(
        checked > members.len(),
        "dependencies state rust_version too"
    );
    assert!(
        too_new.is_empty(),
        "locked dependencies above rust-version {msrv}: {too_new:?}"
    );
}

#[test]
fn the_readme_states_the_same_minimum() {
    let msrv = workspace_rust_version();
    let readme = std::fs::read_to_string(workspace_root().join("README.md")).unwrap();
    assert!(
        readme.contains(&format!("stable, {msrv} or newer")),
        "README's install section must name rust {msrv} as the minimum"
    );
}

#[test]
fn versions_compare_part_by_part() {
    assert!(parse_version("1.88") < parse_version("1.88.1"));
    assert!(parse_version("1.9") < parse_version("1.88"));
    assert!(parse_version("1.100") > parse_version("1.88.0"));
}
