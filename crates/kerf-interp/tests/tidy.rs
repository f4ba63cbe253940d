//! Code rules checked mechanically over the workspace's source (every
//! `crates/*/src/**.rs`, test code left out: `#[cfg(test)]` modules, inline
//! or in a file of their own, and `#[test]` functions), read as syntax trees:
//!
//! - a motion command (`Canon::Rapid`, `Feed`, `Arc`, `Thread`) is built
//!   only in the move seam, kerf-interp/src/interp/mover.rs: nothing else
//!   can set the machine position and emit a move without the travel and
//!   stored stroke checks;
//! - no function is longer than [`MAX_FN_LINES`] lines, from `fn` to its
//!   closing brace.

use std::path::{Path, PathBuf};

use syn::spanned::Spanned;
use syn::visit::{self, Visit};

/// The longest function allowed, in lines.
const MAX_FN_LINES: usize = 120;

/// The one file that may build a motion `Canon`.
const MOVE_SEAM: &str = "crates/kerf-interp/src/interp/mover.rs";

const MOTION: [&str; 4] = ["Rapid", "Feed", "Arc", "Thread"];

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Every `.rs` file under `crates/*/src`, as (path from the workspace root,
/// text).
fn sources() -> Vec<(String, String)> {
    let root = workspace();
    let mut out = Vec::new();
    let mut crates: Vec<_> = std::fs::read_dir(root.join("crates"))
        .expect("crates/")
        .map(|e| e.expect("entry").path())
        .collect();
    crates.sort();
    for c in crates {
        walk(&root, &c.join("src"), &mut out);
    }
    assert!(out.len() > 20, "found only {} source files", out.len());
    out
}

fn walk(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<_> = rd.map(|e| e.expect("entry").path()).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            walk(root, &p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&p).expect("read source");
            let rel = p
                .strip_prefix(root)
                .expect("under the root")
                .to_string_lossy()
                .replace('\\', "/");
            let rel = rel.trim_start_matches("./").to_string();
            out.push((rel, text));
        }
    }
}

/// True for `#[test]` and `#[cfg(test)]` (alone or in `all(test, …)`).
fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        let p = a.path();
        if p.is_ident("test") {
            return true;
        }
        if !p.is_ident("cfg") {
            return false;
        }
        let mut test = false;
        let _ = a.parse_nested_meta(|m| {
            if m.path.is_ident("test") {
                test = true;
            }
            Ok(())
        });
        test
    })
}

/// What the rules found in one file.
#[derive(Default)]
struct Findings {
    /// (function name, first line, lines).
    long_fns: Vec<(String, usize, usize)>,
    /// Lines where a motion `Canon` is built.
    motion_builds: Vec<usize>,
    /// `#[cfg(test)] mod NAME;` declarations: test modules in files of
    /// their own, left out like inline ones.
    test_mod_files: Vec<String>,
}

impl<'ast> Visit<'ast> for Findings {
    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        if !is_test(&m.attrs) {
            visit::visit_item_mod(self, m);
        } else if m.content.is_none() {
            self.test_mod_files.push(m.ident.to_string());
        }
    }

    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        if !is_test(&f.attrs) {
            self.measure(&f.sig, &f.block);
            visit::visit_item_fn(self, f);
        }
    }

    fn visit_impl_item_fn(&mut self, f: &'ast syn::ImplItemFn) {
        if !is_test(&f.attrs) {
            self.measure(&f.sig, &f.block);
            visit::visit_impl_item_fn(self, f);
        }
    }

    fn visit_trait_item_fn(&mut self, f: &'ast syn::TraitItemFn) {
        if let Some(b) = &f.default {
            if !is_test(&f.attrs) {
                self.measure(&f.sig, b);
            }
        }
        visit::visit_trait_item_fn(self, f);
    }

    fn visit_expr_struct(&mut self, e: &'ast syn::ExprStruct) {
        let segs: Vec<String> = e
            .path
            .segments
            .iter()
            .map(|s| s.ident.to_string())
            .collect();
        if let [.., ty, variant] = segs.as_slice() {
            if ty == "Canon" && MOTION.contains(&variant.as_str()) {
                self.motion_builds.push(e.path.span().start().line);
            }
        }
        visit::visit_expr_struct(self, e);
    }
}

impl Findings {
    fn measure(&mut self, sig: &syn::Signature, body: &syn::Block) {
        let first = sig.fn_token.span().start().line;
        let last = body.brace_token.span.close().end().line;
        let n = last + 1 - first;
        if n > MAX_FN_LINES {
            self.long_fns.push((sig.ident.to_string(), first, n));
        }
    }
}

/// The files a `#[cfg(test)] mod NAME;` in `path` may live in.
fn module_files(path: &str, name: &str) -> [String; 2] {
    let (dir, file) = path.rsplit_once('/').expect("a path under crates/");
    let base = match file {
        "lib.rs" | "main.rs" | "mod.rs" => dir.to_string(),
        _ => format!("{dir}/{}", file.trim_end_matches(".rs")),
    };
    [format!("{base}/{name}.rs"), format!("{base}/{name}/mod.rs")]
}

fn findings() -> Vec<(String, Findings)> {
    let all: Vec<(String, Findings)> = sources()
        .into_iter()
        .map(|(path, text)| {
            let file = syn::parse_file(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
            let mut f = Findings::default();
            f.visit_file(&file);
            (path, f)
        })
        .collect();
    let test_files: Vec<String> = all
        .iter()
        .flat_map(|(path, f)| f.test_mod_files.iter().flat_map(|m| module_files(path, m)))
        .collect();
    all.into_iter()
        .filter(|(path, _)| !test_files.contains(path))
        .collect()
}

#[test]
fn motion_commands_are_built_only_in_the_move_seam() {
    let mut bad = Vec::new();
    let mut in_seam = 0;
    for (path, f) in findings() {
        if path == MOVE_SEAM {
            in_seam = f.motion_builds.len();
        } else {
            bad.extend(f.motion_builds.iter().map(|l| format!("{path}:{l}")));
        }
    }
    assert!(
        bad.is_empty(),
        "motion Canon built outside {MOVE_SEAM}:\n{}",
        bad.join("\n")
    );
    // The rule sees the seam's own builds (it is not vacuous).
    assert!(in_seam >= 4, "found {in_seam} motion builds in {MOVE_SEAM}");
}

#[test]
fn no_function_is_longer_than_the_limit() {
    let mut bad = Vec::new();
    for (path, f) in findings() {
        for (name, line, n) in &f.long_fns {
            bad.push(format!("{path}:{line} {name}: {n} lines"));
        }
    }
    assert!(
        bad.is_empty(),
        "functions over {MAX_FN_LINES} lines:\n{}",
        bad.join("\n")
    );
}

/// The measurer itself, on text whose answer is known.
#[test]
fn the_rules_see_what_they_should() {
    let body = "    x += 1;\n".repeat(MAX_FN_LINES - 2);
    let text = format!(
        "fn ok() {{\n{body}}}\nfn long() {{\n{body}    x += 1;\n}}\n\
         #[cfg(test)]\nmod tests {{ fn long_test() {{\n{body}{body}}} }}\n\
         fn build() {{ let c = Canon::Feed {{ m, feed }}; if let Canon::Rapid {{ .. }} = c {{}} }}\n"
    );
    let file = syn::parse_file(&text).unwrap();
    let mut f = Findings::default();
    f.visit_file(&file);
    assert_eq!(
        f.long_fns,
        vec![("long".to_string(), MAX_FN_LINES + 1, MAX_FN_LINES + 1)]
    );
    // One build (the pattern is not one), on the last line.
    assert_eq!(f.motion_builds, vec![text.lines().count()]);
}

#[test]
fn out_of_line_test_modules_are_found_beside_their_parent() {
    assert_eq!(
        module_files("crates/a/src/sinks/plot.rs", "tests"),
        [
            "crates/a/src/sinks/plot/tests.rs".to_string(),
            "crates/a/src/sinks/plot/tests/mod.rs".to_string()
        ]
    );
    assert_eq!(
        module_files("crates/a/src/lib.rs", "tests")[0],
        "crates/a/src/tests.rs"
    );
    let file = syn::parse_file("#[cfg(test)]\nmod tests;\nmod real;\n").unwrap();
    let mut f = Findings::default();
    f.visit_file(&file);
    assert_eq!(f.test_mod_files, ["tests"]);
}
