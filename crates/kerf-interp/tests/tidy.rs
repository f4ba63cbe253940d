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
//!   the interpreter asks the dialect's tables what a code means;
//! - likewise no number of an M code the interpreter acts on (a table M
//!   code whose action or side effect is not just an auxiliary event:
//!   M02/M30, M98/M99, M03-M09, M76/M77 …) as such a literal, integer or
//!   float: M10 and up anywhere, the lower ones where the other side is
//!   an M code (`m`, `*_m`, `m_*`, `.m[i].0`, `mcode(…)`).

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

/// Calls whose argument is an M code number.
const M_CALLS: [&str; 2] = ["has_m", "mcode"];

/// M codes below this are matched only against an M code operand (0-9
/// are too common as plain numbers to tell apart).
const M_ANYWHERE: u16 = 10;

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
    /// Lines matching a literal that is the number of an M code the
    /// interpreter acts on.
    m_literals: Vec<usize>,
    /// The M code numbers the M rule looks for; empty: the rule is off.
    mcodes: Vec<u16>,
    /// Inside the patterns of a `match` (or `matches!`) on an M code.
    m_scrutinee: bool,
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
        let m = self.m_scrutinee;
        match p {
            syn::Pat::Lit(l) => {
                self.code_lit(&l.lit);
                self.m_lit(&l.lit, m);
            }
            syn::Pat::Range(r) => {
                for e in [&r.start, &r.end].into_iter().flatten() {
                    if let syn::Expr::Lit(l) = &**e {
                        self.code_lit(&l.lit);
                        self.m_lit(&l.lit, m);
                    }
                }
            }
            _ => {}
        }
        visit::visit_pat(self, p);
    }

    fn visit_expr_match(&mut self, e: &'ast syn::ExprMatch) {
        self.visit_expr(&e.expr);
        let outer = self.m_scrutinee;
        for arm in &e.arms {
            self.m_scrutinee = is_m_code(&e.expr);
            self.visit_pat(&arm.pat);
            self.m_scrutinee = outer;
            self.visit_expr(&arm.body);
        }
    }

    fn visit_expr_binary(&mut self, e: &'ast syn::ExprBinary) {
        if matches!(e.op, syn::BinOp::Eq(_) | syn::BinOp::Ne(_)) {
            for (side, other) in [(&*e.left, &*e.right), (&*e.right, &*e.left)] {
                if let syn::Expr::Lit(l) = side {
                    self.code_lit(&l.lit);
                    self.m_lit(&l.lit, is_m_code(other));
                }
            }
        }
        visit::visit_expr_binary(self, e);
    }

    fn visit_expr_method_call(&mut self, e: &'ast syn::ExprMethodCall) {
        let g = CODE_CALLS.iter().any(|c| e.method == c);
        let m = M_CALLS.iter().any(|c| e.method == c);
        for a in &e.args {
            if let syn::Expr::Lit(l) = a {
                if g {
                    self.code_lit(&l.lit);
                }
                if m {
                    self.m_lit(&l.lit, true);
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
                let outer = self.m_scrutinee;
                self.m_scrutinee = is_m_code(&e);
                self.visit_pat(&p);
                self.m_scrutinee = outer;
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

    /// An integer or float literal that is the number of an M code the
    /// interpreter acts on: M10 and up anywhere, lower ones where
    /// `m_operand` (the other side is an M code).
    fn m_lit(&mut self, l: &syn::Lit, m_operand: bool) {
        let v = match l {
            syn::Lit::Int(i) => i.base10_parse::<u16>().ok(),
            syn::Lit::Float(f) => f
                .base10_parse::<f64>()
                .ok()
                .filter(|v| v.fract() == 0.0 && (0.0..=65535.0).contains(v))
                .map(|v| v as u16),
            _ => None,
        };
        if let Some(v) = v {
            if (v >= M_ANYWHERE || m_operand) && self.mcodes.contains(&v) {
                self.m_literals.push(l.span().start().line);
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

/// Whether an expression is an M code by its name: `m`, `mc`, `*_m`,
/// `m_*`, a field or index of one (`self.words.m[i].0`), `mcode(…)`.
fn is_m_code(e: &syn::Expr) -> bool {
    let named = |s: String| s == "m" || s == "mc" || s.starts_with("m_") || s.ends_with("_m");
    match e {
        syn::Expr::Path(p) => p
            .path
            .segments
            .last()
            .is_some_and(|s| named(s.ident.to_string())),
        syn::Expr::Field(f) => match &f.member {
            syn::Member::Named(n) => named(n.to_string()),
            syn::Member::Unnamed(_) => is_m_code(&f.base),
        },
        syn::Expr::Index(i) => is_m_code(&i.expr),
        syn::Expr::MethodCall(c) => M_CALLS.iter().any(|m| c.method == m),
        syn::Expr::Unary(u) => is_m_code(&u.expr),
        syn::Expr::Paren(p) => is_m_code(&p.expr),
        syn::Expr::Cast(c) => is_m_code(&c.expr),
        syn::Expr::Reference(r) => is_m_code(&r.expr),
        _ => false,
    }
}

/// The M code numbers of the three dialects' tables that the interpreter
/// acts on (an action or side effect besides the auxiliary event).
fn acted_mcodes() -> Vec<u16> {
    use kerf_interp::dialect::{MAction, MAlso};
    use kerf_interp::{Dialect, DialectId};
    let mut v: Vec<u16> = [DialectId::Hx, DialectId::Puma, DialectId::Hurco]
        .into_iter()
        .flat_map(|d| Dialect::get(d).mcodes.iter())
        .filter(|m| m.action != MAction::Aux || m.also != MAlso::Nothing)
        .map(|m| m.code)
        .collect();
    v.sort_unstable();
    v.dedup();
    v
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
    let mcodes = acted_mcodes();
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
                mcodes: mcodes.clone(),
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

/// What `pick` finds in the interpreter's files outside dialect/ (as
/// "LINE: what"), each prefixed with its file, and how many files were
/// walked.
fn outside_dialect(pick: impl Fn(&Findings) -> Vec<String>) -> (Vec<String>, usize) {
    let mut bad = Vec::new();
    let mut checked = 0;
    for (path, f) in findings() {
        if !path.starts_with(INTERP_SRC) || path.starts_with(DIALECT_DIR) {
            continue;
        }
        checked += 1;
        bad.extend(pick(&f).into_iter().map(|l| format!("{path}:{l}")));
    }
    (bad, checked)
}

/// The lines as "LINE: what".
fn named(lines: &[usize], what: &str) -> Vec<String> {
    lines.iter().map(|l| format!("{l}: {what}")).collect()
}

#[test]
fn dialect_ids_and_code_literals_only_in_dialect() {
    let (bad, checked) = outside_dialect(|f| {
        let mut v = named(&f.dialect_ids, "dialect id");
        v.extend(named(&f.code_literals, "G code number"));
        v
    });
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
fn acted_m_code_numbers_only_in_dialect() {
    let (bad, checked) = outside_dialect(|f| named(&f.m_literals, "M code number"));
    assert!(
        bad.is_empty(),
        "M code numbers matched outside {DIALECT_DIR}: ask the dialect's M \
         table (an MAction, an MAlso) instead:\n{}",
        bad.join("\n")
    );
    assert!(checked > 30, "checked only {checked} files");
    // The rule looks for the codes it should (it is not vacuous).
    let m = acted_mcodes();
    assert!([2, 30, 98, 99].iter().all(|c| m.contains(c)), "{m:?}");
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

/// The M rule on text whose answer is known: M10 and up in comparisons,
/// patterns, `matches!` and lookups; the low codes only against an M
/// code operand; plain numbers, auxiliary-only codes and test code not.
#[test]
fn the_m_code_rule_sees_what_it_should() {
    let text = "fn f(m: u32, n: u32, code_m: f64, k: u32) {\n\
                if m == 98 || n == 99 {}\n\
                match m { 2 | 30 => {} _ => {} }\n\
                let _ = matches!(self.words.m[i].0, 6);\n\
                let _ = code_m != 2.0 || n == 2 || k == 6;\n\
                let _ = self.mcode(3);\n\
                match n { 0 | 1 | 2 => {} _ => {} }\n\
                let _ = n == 12345;\n\
                }\n\
                #[cfg(test)]\nmod tests { fn t() { let _ = m == 98; } }\n";
    let file = syn::parse_file(text).unwrap();
    let mut f = Findings {
        mcodes: acted_mcodes(),
        ..Findings::default()
    };
    f.visit_file(&file);
    // Line 2: M98 against m, M99 though n is not an M code (99 ≥ 10);
    // line 3: M02 and M30 in a match on m; line 4: M06 against an M
    // field; line 5: M02 as a float against code_m (not n == 2, k == 6);
    // line 6: a lookup; line 7: small numbers matched on n are not codes.
    assert_eq!(f.m_literals, vec![2, 2, 3, 3, 4, 5, 6]);
    // 12345 is no M code of any table.
    let lone = syn::parse_file("fn g(m: u32) { let _ = m == 12345; }").unwrap();
    let mut g = Findings {
        mcodes: acted_mcodes(),
        ..Findings::default()
    };
    g.visit_file(&lone);
    assert!(g.m_literals.is_empty());
}
