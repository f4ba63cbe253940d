//! Code rules checked mechanically over the workspace's source (every
//! `crates/*/src/**.rs`, test code left out: `#[cfg(test)]` modules, in
//! line or in their own file, and `#[test]` functions), read as syntax
//! trees:
//!
//! - a motion command (`Canon::Rapid`, `Feed`, `Arc`, `Thread`) is built
//!   only in the move seam, kerf-interp/src/interp/mover.rs: nothing else
//!   can set the machine position and emit a move without the travel and
//!   stored stroke checks;
//! - no function is longer than [`MAX_FN_LINES`] lines, from `fn` to its
//!   closing brace;
//! - in kerf-interp outside `src/dialect/`, no dialect id
//!   (`DialectId::Hx` …) and no G code number (value×10) matched as a
//!   literal (a pattern, an `==`/`!=` operand, a `has_g`/`gcode` argument):
//!   the interpreter asks the dialect's tables what a code means.

use std::path::{Path, PathBuf};

use syn::spanned::Spanned;
use syn::visit::{self, Visit};

/// The longest function allowed, in lines.
const MAX_FN_LINES: usize = 120;

/// The one file that may build a motion `Canon`.
const MOVE_SEAM: &str = "crates/kerf-interp/src/interp/mover.rs";

const MOTION: [&str; 4] = ["Rapid", "Feed", "Arc", "Thread"];

/// The source the dialect rule covers, and the part of it exempt.
const INTERP_SRC: &str = "crates/kerf-interp/src/";
const DIALECT_DIR: &str = "crates/kerf-interp/src/dialect/";

/// Calls whose integer argument is a G code number.
const CODE_CALLS: [&str; 2] = ["has_g", "gcode"];

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
    /// Lines naming a dialect id (`DialectId::X`).
    dialect_ids: Vec<usize>,
    /// Lines matching an integer literal that is a G code number.
    code_literals: Vec<usize>,
    /// The G code numbers (value×10) of the dialects' tables that the
    /// code-literal rule looks for; empty: the rule is off.
    codes: Vec<u16>,
}

impl<'ast> Visit<'ast> for Findings {
    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        if !is_test(&m.attrs) {
            visit::visit_item_mod(self, m);
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

    fn visit_path(&mut self, p: &'ast syn::Path) {
        let n = p.segments.len();
        if n >= 2 && p.segments[n - 2].ident == "DialectId" {
            self.dialect_ids.push(p.span().start().line);
        }
        visit::visit_path(self, p);
    }

    fn visit_pat(&mut self, p: &'ast syn::Pat) {
        match p {
            syn::Pat::Lit(l) => self.code_lit(&l.lit),
            syn::Pat::Range(r) => {
                for e in [&r.start, &r.end].into_iter().flatten() {
                    if let syn::Expr::Lit(l) = &**e {
                        self.code_lit(&l.lit);
                    }
                }
            }
            _ => {}
        }
        visit::visit_pat(self, p);
    }

    fn visit_expr_binary(&mut self, e: &'ast syn::ExprBinary) {
        if matches!(e.op, syn::BinOp::Eq(_) | syn::BinOp::Ne(_)) {
            for side in [&*e.left, &*e.right] {
                if let syn::Expr::Lit(l) = side {
                    self.code_lit(&l.lit);
                }
            }
        }
        visit::visit_expr_binary(self, e);
    }

    fn visit_expr_method_call(&mut self, e: &'ast syn::ExprMethodCall) {
        if CODE_CALLS.iter().any(|c| e.method == c) {
            for a in &e.args {
                if let syn::Expr::Lit(l) = a {
                    self.code_lit(&l.lit);
                }
            }
        }
        visit::visit_expr_method_call(self, e);
    }

    fn visit_macro(&mut self, m: &'ast syn::Macro) {
        // `matches!(expr, pattern)`: the pattern is checked like any other.
        if m.path.is_ident("matches") {
            let parsed = m.parse_body_with(|input: syn::parse::ParseStream| {
                let e: syn::Expr = input.parse()?;
                input.parse::<syn::Token![,]>()?;
                let p = syn::Pat::parse_multi_with_leading_vert(input)?;
                let _: proc_macro2::TokenStream = input.parse()?;
                Ok((e, p))
            });
            if let Ok((e, p)) = parsed {
                self.visit_expr(&e);
                self.visit_pat(&p);
            }
        }
        visit::visit_macro(self, m);
    }
}

impl Findings {
    /// An integer literal that is one of the tables' G code numbers (G04
    /// and up: 0-30 are too common as plain numbers to tell apart).
    fn code_lit(&mut self, l: &syn::Lit) {
        if let syn::Lit::Int(i) = l {
            if let Ok(v) = i.base10_parse::<u16>() {
                if v >= 40 && self.codes.contains(&v) {
                    self.code_literals.push(i.span().start().line);
                }
            }
        }
    }

    fn measure(&mut self, sig: &syn::Signature, body: &syn::Block) {
        let first = sig.fn_token.span().start().line;
        let last = body.brace_token.span.close().end().line;
        let n = last + 1 - first;
        if n > MAX_FN_LINES {
            self.long_fns.push((sig.ident.to_string(), first, n));
        }
    }
}

/// Every G code number of the three dialects' tables.
fn table_codes() -> Vec<u16> {
    use kerf_interp::{Dialect, DialectId};
    let mut v: Vec<u16> = [DialectId::Hx, DialectId::Puma, DialectId::Hurco]
        .into_iter()
        .flat_map(|d| Dialect::get(d).gcodes.iter().map(|g| g.code10))
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// The files of the test modules a file declares out of line
/// (`#[cfg(test)] mod tests;` in `a/b.rs` is `a/b/tests.rs` or
/// `a/b/tests/mod.rs`).
fn test_module_files(path: &str, file: &syn::File) -> Vec<String> {
    let (dir, stem) = path.rsplit_once('/').unwrap_or(("", path));
    let stem = stem.trim_end_matches(".rs");
    let base = if matches!(stem, "mod" | "lib" | "main") {
        dir.to_string()
    } else {
        format!("{dir}/{stem}")
    };
    let mut out = Vec::new();
    for item in &file.items {
        if let syn::Item::Mod(m) = item {
            if m.content.is_none() && is_test(&m.attrs) {
                out.push(format!("{base}/{}.rs", m.ident));
                out.push(format!("{base}/{}/mod.rs", m.ident));
            }
        }
    }
    out
}

fn findings() -> Vec<(String, Findings)> {
    let codes = table_codes();
    let parsed: Vec<(String, syn::File)> = sources()
        .into_iter()
        .map(|(path, text)| {
            let file = syn::parse_file(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
            (path, file)
        })
        .collect();
    let tests: Vec<String> = parsed
        .iter()
        .flat_map(|(path, file)| test_module_files(path, file))
        .collect();
    parsed
        .into_iter()
        .filter(|(path, _)| !tests.contains(path))
        .map(|(path, file)| {
            let mut f = Findings {
                codes: codes.clone(),
                ..Findings::default()
            };
            f.visit_file(&file);
            (path, f)
        })
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
fn dialect_ids_and_code_literals_only_in_dialect() {
    let mut bad = Vec::new();
    let mut checked = 0;
    for (path, f) in findings() {
        if !path.starts_with(INTERP_SRC) || path.starts_with(DIALECT_DIR) {
            continue;
        }
        checked += 1;
        bad.extend(
            f.dialect_ids
                .iter()
                .map(|l| format!("{path}:{l}: dialect id")),
        );
        bad.extend(
            f.code_literals
                .iter()
                .map(|l| format!("{path}:{l}: G code number")),
        );
    }
    assert!(
        bad.is_empty(),
        "dialect ids or G code numbers matched outside {DIALECT_DIR}: ask the \
         dialect's tables (a meaning, a capability) instead:\n{}",
        bad.join("\n")
    );
    // The rule walked the interpreter (it is not vacuous).
    assert!(checked > 30, "checked only {checked} files");
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
    // A test module in its own file is test code; another module is not.
    let decl = syn::parse_file("#[cfg(test)]\nmod tests;\nmod real;\n").unwrap();
    assert_eq!(
        test_module_files("crates/a/src/sinks/plot.rs", &decl),
        [
            "crates/a/src/sinks/plot/tests.rs",
            "crates/a/src/sinks/plot/tests/mod.rs"
        ]
    );
    assert_eq!(
        test_module_files("crates/a/src/lib.rs", &decl),
        ["crates/a/src/tests.rs", "crates/a/src/tests/mod.rs"]
    );
}

/// The dialect rule on text whose answer is known: ids in expressions
/// and patterns, code numbers in patterns, ranges, `matches!`,
/// comparisons and lookups; plain numbers and test code not.
#[test]
fn the_dialect_rule_sees_what_it_should() {
    let text = "fn f(d: DialectId, c: u16, n: u32) {\n\
                if d == DialectId::Hx {}\n\
                match (d, c) { (DialectId::Puma, 500) => {} _ => {} }\n\
                match c { 700..=760 => {} _ => {} }\n\
                let _ = matches!(c, 170 | 180);\n\
                let _ = c == 400 || n == 7 || n == 1000;\n\
                let _ = self.words.has_g(800);\n\
                let _ = [0u16; 32];\n\
                }\n\
                #[cfg(test)]\nmod tests { fn t() { let _ = DialectId::Hx; let _ = c == 400; } }\n";
    let file = syn::parse_file(text).unwrap();
    let mut f = Findings {
        codes: table_codes(),
        ..Findings::default()
    };
    f.visit_file(&file);
    assert_eq!(f.dialect_ids, vec![2, 3]);
    assert_eq!(f.code_literals, vec![3, 4, 4, 5, 5, 6, 7]);
}
