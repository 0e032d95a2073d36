//! No new import cycles between source files (issue 26, item 2).
//!
//! Reads every `.rs` file of the library (`src/`) and of the solver
//! (`solver/src/`), one module per file (`src/a/b.rs` and `src/a/b/mod.rs` are
//! both module `a::b`), and collects each file's references to other modules of
//! its own crate:
//!
//! * `use` trees, with braces, globs, `self` and `as` (`use crate::..`,
//!   `use super::..`, `use self::..`, and `use child::..` for a child module);
//! * paths in code that start with `crate::`, `$crate::`, `super::` or `self::`.
//!
//! A path resolves to the file of the longest module prefix that exists as a
//! file: a reference to an item of a module (`crate::ball::Ball`) is a reference
//! to that module's file (`src/ball.rs`), also when the item is re-exported
//! there from elsewhere. Inline modules (`mod tests { .. }`) belong to their
//! file, and `super::` inside them steps out of them first. References from a
//! module to its own descendants (a `mod.rs` declaring its children, re-exporting
//! or dispatching to them) are not edges; references from a child to its parent
//! or any other module (`super::`, `crate::..`) are. Test-only code (an item
//! under `#[cfg(test)]`, such as `mod tests { .. }`, whose unit tests compare a
//! method with its siblings) is not library structure and is skipped. Comments,
//! doc comments (intra-doc links), string and char literals are ignored, and so
//! are macro invocations (`macro_rules!` scoping is textual).
//!
//! The file graph's strongly connected components of more than one file are the
//! cycles. [`KNOWN_CYCLES`] lists the ones that exist today; the test fails on
//! any cycle not in it, and on any entry of it that is no longer a cycle (so the
//! list shrinks as the refactor of issue 26 lands: delete the entry).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The cycles that exist today, each as the sorted set of its files (paths from
/// the workspace root). Issue 26 item 2 removes them; delete an entry when its
/// cycle is gone (the test says so).
const KNOWN_CYCLES: &[(&[&str], &str)] = &[];

/// A token of stripped Rust source: an identifier, `::`, or one punctuation character.
#[derive(Clone, Debug, PartialEq)]
struct Tok {
    text: String,
    line: usize,
}

/// Tokens of `src` with comments, string, byte-string, raw-string and char
/// literals removed (lifetimes are skipped too). Numbers become one token each.
fn tokens(src: &str) -> Vec<Tok> {
    let c: Vec<char> = src.chars().collect();
    let n = c.len();
    let mut out = Vec::new();
    let mut line = 1;
    let mut i = 0;
    let at = |k: usize| if k < n { c[k] } else { '\0' };
    while i < n {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && at(i + 1) == '/' {
            while i < n && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && at(i + 1) == '*' {
            let mut depth = 0;
            while i < n {
                if c[i] == '/' && at(i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if c[i] == '\n' {
                        line += 1;
                    }
                    i += 1;
                }
            }
        } else if (ch == 'r' || (ch == 'b' && at(i + 1) == 'r')) && {
            let k = if ch == 'b' { i + 2 } else { i + 1 };
            let mut j = k;
            while at(j) == '#' {
                j += 1;
            }
            at(j) == '"' && (i == 0 || !is_ident_char(c[i - 1]))
        } {
            // raw string r"..", r#".."#, br#".."#
            let mut j = if ch == 'b' { i + 2 } else { i + 1 };
            let mut hashes = 0;
            while at(j) == '#' {
                hashes += 1;
                j += 1;
            }
            j += 1; // opening quote
            loop {
                if j >= n {
                    break;
                }
                if c[j] == '\n' {
                    line += 1;
                }
                if c[j] == '"' && (1..=hashes).all(|h| at(j + h) == '#') {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            i = j;
        } else if ch == '"' {
            let mut j = i + 1;
            while j < n && c[j] != '"' {
                if c[j] == '\\' {
                    j += 1;
                }
                if at(j) == '\n' {
                    line += 1;
                }
                j += 1;
            }
            i = j + 1;
        } else if ch == '\'' {
            if at(i + 1) == '\\' {
                // escaped char literal: '\n', '\'', '\u{..}'
                let mut j = i + 2;
                while j < n && c[j] != '\'' {
                    j += 1;
                }
                i = j + 1;
            } else if at(i + 2) == '\'' {
                i += 3; // 'x'
            } else {
                i += 1; // a lifetime or label: its name follows as an identifier
                while i < n && is_ident_char(c[i]) {
                    i += 1;
                }
            }
        } else if is_ident_char(ch) {
            let s = i;
            while i < n && is_ident_char(c[i]) {
                i += 1;
            }
            let mut text: String = c[s..i].iter().collect();
            if text == "r" && at(i) == '#' && is_ident_char(at(i + 1)) {
                // raw identifier r#name
                let s = i + 1;
                i = s;
                while i < n && is_ident_char(c[i]) {
                    i += 1;
                }
                text = c[s..i].iter().collect();
            }
            out.push(Tok { text, line });
        } else if ch == ':' && at(i + 1) == ':' {
            out.push(Tok {
                text: "::".into(),
                line,
            });
            i += 2;
        } else if ch == '$' && c[i + 1..].starts_with(&['c', 'r', 'a', 't', 'e']) {
            out.push(Tok {
                text: "crate".into(),
                line,
            });
            i += 6;
        } else {
            out.push(Tok {
                text: ch.to_string(),
                line,
            });
            i += 1;
        }
    }
    out
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

fn is_ident(t: &str) -> bool {
    t.chars()
        .next()
        .is_some_and(|c| c.is_alphabetic() || c == '_')
}

/// One crate's source files: module path -> file (relative to the workspace root).
struct Crate {
    modules: BTreeMap<Vec<String>, String>,
}

/// The module path of a file under a crate's `src/`: `lib.rs` is the root,
/// `a/b.rs` and `a/b/mod.rs` are `a::b`.
fn module_of(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().unwrap();
    let stem = last.strip_suffix(".rs").unwrap();
    if stem != "mod" && !(parts.is_empty() && (stem == "lib" || stem == "main")) {
        parts.push(stem.to_string());
    }
    parts
}

fn rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rs_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// An edge: source file -> (target file -> first line of the source that refers to it).
type Graph = BTreeMap<String, BTreeMap<String, usize>>;

/// Reads a crate's files from disk: (file name from the workspace root, module path, text).
fn read_crate(root: &Path, src: &str) -> Vec<(String, Vec<String>, String)> {
    let dir = root.join(src);
    let mut files = Vec::new();
    rs_files(&dir, &mut files);
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let rel = p.strip_prefix(&dir).unwrap();
            let name = format!("{src}/{}", rel.to_string_lossy().replace('\\', "/"));
            (name, module_of(rel), std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

/// The file graph of one crate, given its files as (name, module path, text).
fn file_graph(files: &[(String, Vec<String>, String)]) -> Graph {
    let krate = Crate {
        modules: files
            .iter()
            .map(|(f, m, _)| (m.clone(), f.clone()))
            .collect(),
    };
    let mut graph = Graph::new();
    for (file, module, text) in files {
        let edges = graph.entry(file.clone()).or_default();
        for (path, cur, line) in references(&tokens(text), module) {
            let Some(abs) = krate.absolute(&path, &cur) else {
                continue;
            };
            // the longest prefix that is a file module (the root always is)
            let target_mod = (0..=abs.len())
                .rev()
                .map(|k| abs[..k].to_vec())
                .find(|m| krate.modules.contains_key(m));
            let Some(target_mod) = target_mod else {
                continue;
            };
            // a module referring to itself or to its own descendants is not an edge
            if target_mod.starts_with(module) {
                continue;
            }
            let target = krate.modules[&target_mod].clone();
            edges.entry(target).or_insert(line);
        }
    }
    graph
}

impl Crate {
    /// `path` (as written, inside module `cur`) as a path from the crate root,
    /// or None when it does not start in this crate (an external crate, a local name).
    fn absolute(&self, path: &[String], cur: &[String]) -> Option<Vec<String>> {
        let first = path.first()?;
        let mut abs: Vec<String> = match first.as_str() {
            "crate" => path[1..].to_vec(),
            "self" => cur.iter().chain(&path[1..]).cloned().collect(),
            "super" => {
                let ups = path.iter().take_while(|s| *s == "super").count();
                if ups > cur.len() {
                    return None;
                }
                cur[..cur.len() - ups]
                    .iter()
                    .chain(&path[ups..])
                    .cloned()
                    .collect()
            }
            _ => {
                // a child module of the current one (a file module)
                let mut child = cur.to_vec();
                child.push(first.clone());
                if !self.modules.contains_key(&child) {
                    return None;
                }
                cur.iter().chain(path).cloned().collect()
            }
        };
        abs.retain(|s| s != "self");
        Some(abs)
    }
}

/// The module paths referred to in a file: (path as written, the module it is
/// written in (inline modules included), line).
fn references(toks: &[Tok], file_module: &[String]) -> Vec<(Vec<String>, Vec<String>, usize)> {
    let mut out = Vec::new();
    // inline modules: (name, brace depth inside it)
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let cur = |inline: &Vec<(String, usize)>| -> Vec<String> {
        file_module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(m, _)| m.clone()))
            .collect()
    };
    let t = |k: usize| toks.get(k).map(|t| t.text.as_str()).unwrap_or("");
    let mut i = 0;
    while i < toks.len() {
        match t(i) {
            "{" => depth += 1,
            "}" => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth = depth.saturating_sub(1);
            }
            "mod" if is_ident(t(i + 1)) && t(i + 2) == "{" => {
                depth += 1;
                inline.push((t(i + 1).to_string(), depth));
                i += 3;
                continue;
            }
            "#" if t(i + 1) == "["
                && t(i + 2) == "cfg"
                && t(i + 3) == "("
                && t(i + 4) == "test"
                && t(i + 5) == ")"
                && t(i + 6) == "]" =>
            {
                // a test-only item (`mod tests { .. }`, a `use`, a fn): skip it whole,
                // to the `;` that ends it or the `}` that closes its first brace
                let mut j = i + 7;
                while j < toks.len() && t(j) != ";" && t(j) != "{" {
                    j += 1;
                }
                if t(j) == "{" {
                    let mut d = 0usize;
                    while j < toks.len() {
                        match t(j) {
                            "{" => d += 1,
                            "}" => {
                                d -= 1;
                                if d == 0 {
                                    break;
                                }
                            }
                            _ => {}
                        }
                        j += 1;
                    }
                }
                i = j + 1;
                continue;
            }
            "pub" if t(i + 1) == "(" => {
                // visibility: pub(crate), pub(super), pub(in path)
                while i < toks.len() && t(i) != ")" {
                    i += 1;
                }
            }
            "use" => {
                let line = toks[i].line;
                let mut j = i + 1;
                if t(j) == "::" {
                    j += 1;
                }
                let mut paths = Vec::new();
                use_tree(toks, &mut j, Vec::new(), &mut paths);
                let here = cur(&inline);
                out.extend(paths.into_iter().map(|p| (p, here.clone(), line)));
                while j < toks.len() && t(j) != ";" {
                    j += 1;
                }
                i = j + 1;
                continue;
            }
            w @ ("crate" | "super" | "self")
                if t(i + 1) == "::" && (i == 0 || t(i - 1) != "::") =>
            {
                let line = toks[i].line;
                let mut path = vec![w.to_string()];
                let mut j = i + 1;
                while t(j) == "::" && is_ident(t(j + 1)) {
                    path.push(t(j + 1).to_string());
                    j += 2;
                }
                out.push((path, cur(&inline), line));
                i = j;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// Expands a `use` tree starting at `toks[*j]` into full paths (a glob or a
/// braced `self` gives the module's own path).
fn use_tree(toks: &[Tok], j: &mut usize, mut prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
    let t = |k: usize| toks.get(k).map(|t| t.text.as_str()).unwrap_or("");
    loop {
        match t(*j) {
            "{" => {
                *j += 1;
                while t(*j) != "}" && *j < toks.len() {
                    use_tree(toks, j, prefix.clone(), out);
                    if t(*j) == "," {
                        *j += 1;
                    }
                }
                *j += 1;
                return;
            }
            "*" => {
                *j += 1;
                out.push(prefix);
                return;
            }
            s if is_ident(s) => {
                prefix.push(s.to_string());
                *j += 1;
                if t(*j) == "::" {
                    *j += 1;
                    continue;
                }
                if t(*j) == "as" {
                    *j += 2;
                }
                out.push(prefix);
                return;
            }
            _ => return,
        }
    }
}

/// Strongly connected components with more than one file (Tarjan), each sorted.
fn cycles(graph: &Graph) -> Vec<Vec<String>> {
    let names: Vec<&String> = graph.keys().collect();
    let index_of: BTreeMap<&String, usize> =
        names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let adj: Vec<Vec<usize>> = names
        .iter()
        .map(|n| {
            graph[*n]
                .keys()
                .filter_map(|m| index_of.get(m).copied())
                .collect()
        })
        .collect();
    struct State {
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on_stack: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(v: usize, adj: &[Vec<usize>], s: &mut State) {
        s.index[v] = Some(s.next);
        s.low[v] = s.next;
        s.next += 1;
        s.stack.push(v);
        s.on_stack[v] = true;
        for &w in &adj[v] {
            match s.index[w] {
                None => {
                    visit(w, adj, s);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(iw) if s.on_stack[w] => s.low[v] = s.low[v].min(iw),
                _ => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on_stack[w] = false;
                comp.push(w);
                if w == v {
                    break;
                }
            }
            s.out.push(comp);
        }
    }
    let n = names.len();
    let mut s = State {
        index: vec![None; n],
        low: vec![0; n],
        on_stack: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(v, &adj, &mut s);
        }
    }
    let mut out: Vec<Vec<String>> = s
        .out
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|c| {
            let mut c: Vec<String> = c.into_iter().map(|i| names[i].clone()).collect();
            c.sort();
            c
        })
        .collect();
    out.sort();
    out
}

/// The edges inside a cycle, with the line that makes each, for the failure message.
fn describe(graph: &Graph, cycle: &[String]) -> String {
    let mut s = String::new();
    for a in cycle {
        for (b, line) in &graph[a] {
            if cycle.contains(b) {
                s += &format!("\n    {a}:{line} -> {b}");
            }
        }
    }
    s
}

#[test]
fn no_new_import_cycles_between_files() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut graph = Graph::new();
    for src in ["src", "solver/src"] {
        graph.extend(file_graph(&read_crate(root, src)));
    }
    let found = cycles(&graph);
    for c in &found {
        println!("cycle:{}", describe(&graph, c)); // shown with --nocapture
    }
    let known: Vec<Vec<String>> = KNOWN_CYCLES
        .iter()
        .map(|(files, _)| {
            let mut v: Vec<String> = files.iter().map(|f| f.to_string()).collect();
            v.sort();
            v
        })
        .collect();
    let new: Vec<&Vec<String>> = found.iter().filter(|c| !known.contains(c)).collect();
    let gone: Vec<&Vec<String>> = known.iter().filter(|c| !found.contains(c)).collect();
    let mut msg = String::new();
    for c in &new {
        msg += &format!("\nnew import cycle between files (break it; do not add it to KNOWN_CYCLES unless agreed):{}", describe(&graph, c));
    }
    for c in &gone {
        msg += &format!("\nKNOWN_CYCLES entry is no longer a cycle, delete it from tests/it/import_cycles.rs: {c:?}");
    }
    assert!(msg.is_empty(), "{msg}\n(cycles found now: {found:#?})");
}

/// The checker itself: a made-up crate with one cycle through `super::` and a
/// `crate::` path in code, one parent-to-child reference that is not an edge,
/// and references hidden in comments, strings and a `#[cfg(test)]` module.
#[test]
fn checker_finds_a_cycle_and_ignores_parent_to_child() {
    let m = |s: &str| -> Vec<String> {
        s.split("::")
            .filter(|x| !x.is_empty())
            .map(String::from)
            .collect()
    };
    let files = vec![
        ("lib.rs".to_string(), m(""), "pub mod a; pub mod b; pub const K: u32 = 1;".to_string()),
        (
            "a/mod.rs".to_string(),
            m("a"),
            "mod c; pub use c::f; use crate::b::{self as bee, g};\n// crate::b::x in a comment".to_string(),
        ),
        (
            "a/c.rs".to_string(),
            m("a::c"),
            "pub fn f() -> u32 { super::super::K }\n#[cfg(test)] mod tests { use super::*; use crate::b::g; }"
                .to_string(),
        ),
        (
            "b.rs".to_string(),
            m("b"),
            "pub fn g() { let _ = \"crate::a::c\"; let _ = '\\''; crate::a::c::f(); }\nfn h<'x>(v: &'x u8) {}"
                .to_string(),
        ),
    ];
    let graph = file_graph(&files);
    let edges = |f: &str| graph[f].keys().cloned().collect::<Vec<_>>();
    assert_eq!(edges("a/mod.rs"), ["b.rs"]);
    assert_eq!(edges("a/c.rs"), ["lib.rs"]);
    assert_eq!(edges("b.rs"), ["a/c.rs"]);
    assert!(edges("lib.rs").is_empty());
    assert!(cycles(&graph).is_empty(), "{:?}", cycles(&graph));
    // close a loop: c -> b (b -> c already)
    let mut files = files;
    files[2].2 += "\nfn k() { crate::b::g() }";
    let graph = file_graph(&files);
    assert_eq!(cycles(&graph), [["a/c.rs".to_string(), "b.rs".to_string()]]);
}
