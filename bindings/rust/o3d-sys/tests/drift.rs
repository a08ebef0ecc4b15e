//! Drift check between the C headers (`capi/include/o3d/*.h`) and the declarations bindgen wrote
//! for this crate (`$OUT_DIR/o3d_bindings.rs`): every exported function, every `#define` constant
//! and every field of every public struct must be declared, with the same value / in the same
//! order, and nothing extra (a check on build.rs's allowlist and constant typing).
use std::collections::BTreeSet;
use std::path::PathBuf;

const SOURCE: &str = include_str!(concat!(env!("OUT_DIR"), "/o3d_bindings.rs"));

/// The include folder build.rs read (from `O3D_INCLUDE_DIR` or pkg-config).
fn include_dir() -> PathBuf {
    PathBuf::from(env!("O3D_HEADER_DIR"))
}

/// The text of every `o3d/*.h` header, with comments removed.
fn headers() -> Vec<(String, String)> {
    let dir = include_dir().join("o3d");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display())) {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) == Some("h") {
            let text = std::fs::read_to_string(&path).unwrap();
            out.push((path.file_name().unwrap().to_string_lossy().into_owned(), strip_comments(&text)));
        }
    }
    out.sort();
    assert!(out.len() >= 19, "expected the 19 o3d headers in {}, found {}", dir.display(), out.len());
    out
}

fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(tail) = rest.strip_prefix("/*") {
            let end = tail.find("*/").expect("unterminated comment");
            rest = &tail[end + 2..];
            out.push(' ');
        } else if let Some(tail) = rest.strip_prefix("//") {
            rest = tail.find('\n').map_or("", |end| &tail[end..]);
        } else {
            let c = rest.chars().next().unwrap();
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Names of the functions declared `O3D_API ... o3d_xxx(` in the headers.
fn header_functions() -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for (_, text) in headers() {
        // Preprocessor lines (`#define O3D_API __attribute__(...)`) are not declarations.
        let flat: String = text.lines().filter(|l| !l.trim_start().starts_with('#')).collect::<Vec<_>>().join(" ");
        for (pos, _) in flat.match_indices("O3D_API ") {
            let decl = &flat[pos..];
            let paren = decl.find('(').unwrap();
            let before = decl[..paren].trim_end();
            let start = before.rfind(|c: char| !is_ident(c)).map_or(0, |i| i + 1);
            names.insert(before[start..].to_string());
        }
    }
    names
}

/// Names of the functions declared `pub fn o3d_xxx(` in the generated bindings.
fn rust_functions() -> BTreeSet<String> {
    SOURCE
        .match_indices("pub fn ")
        .map(|(pos, m)| {
            let rest = &SOURCE[pos + m.len()..];
            rest[..rest.find('(').unwrap()].to_string()
        })
        .collect()
}

#[test]
fn every_header_function_is_declared_and_nothing_else() {
    let header = header_functions();
    let rust = rust_functions();
    assert!(header.len() >= 190, "parsed only {} functions from the headers", header.len());
    for name in &header {
        assert!(name.starts_with("o3d_"), "odd function name {name:?} parsed from the headers");
    }
    let missing: Vec<_> = header.difference(&rust).collect();
    let extra: Vec<_> = rust.difference(&header).collect();
    assert!(missing.is_empty(), "declared in the headers but not in o3d-sys: {missing:?}");
    assert!(extra.is_empty(), "declared in o3d-sys but not in the headers: {extra:?}");
}

/// Parse "0", "(-1)", "-7" into an integer.
fn parse_int(value: &str) -> Option<i64> {
    value.trim().trim_start_matches('(').trim_end_matches(')').trim().parse().ok()
}

#[test]
fn every_header_constant_is_declared_with_its_value() {
    let mut count = 0;
    for (file, text) in headers() {
        for line in text.lines() {
            let Some(rest) = line.trim_start().strip_prefix("#define ") else { continue };
            let mut parts = rest.splitn(2, char::is_whitespace);
            let name = parts.next().unwrap();
            let Some(value) = parts.next().and_then(parse_int) else { continue }; // macros, guards
            count += 1;
            let needle = format!("pub const {name}: ");
            let pos =
                SOURCE.find(&needle).unwrap_or_else(|| panic!("{file}: constant {name} is not declared in o3d-sys"));
            let decl = &SOURCE[pos..];
            let decl = &decl[..decl.find(';').unwrap()];
            let rust_value = parse_int(&decl[decl.find('=').unwrap() + 1..]).unwrap();
            assert_eq!(rust_value, value, "{file}: {name} is {value} in C but {rust_value} in Rust");
        }
    }
    assert!(count >= 45, "parsed only {count} constants");
}

/// Fields of `typedef struct NAME { ... } NAME_t;` in the headers, in order.
fn header_structs() -> Vec<(String, Vec<String>)> {
    let mut out = Vec::new();
    for (_, text) in headers() {
        for (pos, m) in text.match_indices("typedef struct ") {
            let rest = &text[pos + m.len()..];
            let name_end = rest.find(|c: char| !is_ident(c)).unwrap();
            let name = &rest[..name_end];
            let after = rest[name_end..].trim_start();
            let Some(body) = after.strip_prefix('{') else { continue }; // opaque handle
            let body = &body[..body.find('}').unwrap()];
            let fields = body
                .split(';')
                .map(str::trim)
                .filter(|f| !f.is_empty())
                .map(|f| {
                    // "double R[9]" declares the field R.
                    let f = f.find('[').map_or(f, |bracket| f[..bracket].trim_end());
                    let start = f.rfind(|c: char| !is_ident(c)).map_or(0, |i| i + 1);
                    f[start..].to_string()
                })
                .collect();
            out.push((name.to_string(), fields));
        }
    }
    out
}

#[test]
fn every_header_struct_has_the_same_fields_in_order() {
    let structs = header_structs();
    let names: Vec<_> = structs.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names.iter().copied().collect::<BTreeSet<_>>(),
        [
            "o3d_color_map_non_rigid_options",
            "o3d_color_map_rigid_options",
            "o3d_correspondence_checker",
            "o3d_depth_to_cloud_options",
            "o3d_fgr_options",
            "o3d_global_optimization_options",
            "o3d_global_optimization_summary",
            "o3d_icp_options",
            "o3d_iss_options",
            "o3d_mesh_read_options",
            "o3d_mesh_write_options",
            "o3d_mobius_options",
            "o3d_obb",
            "o3d_obe",
            "o3d_octree_node_info",
            "o3d_odometry_options",
            "o3d_pinhole_intrinsic",
            "o3d_planar_patch_options",
            "o3d_poisson_options",
            "o3d_pose_graph_edge",
            "o3d_progress_options",
            "o3d_ransac_options",
            "o3d_read_options",
            "o3d_reconstruction_options",
            "o3d_render_material",
            "o3d_render_option",
            "o3d_rgbd_options",
            "o3d_search_param",
            "o3d_write_options",
        ]
        .into(),
        "the set of public structs changed: update o3d-sys and tests/layout.rs"
    );
    for (name, fields) in structs {
        let needle = format!("pub struct {name} {{");
        let pos = SOURCE.find(&needle).unwrap_or_else(|| panic!("struct {name} is not declared in o3d-sys"));
        let body = &SOURCE[pos + needle.len()..];
        let body = &body[..body.find('}').unwrap()];
        let rust_fields: Vec<String> = body
            .lines()
            .filter_map(|l| l.trim().strip_prefix("pub "))
            .map(|l| l[..l.find(':').unwrap()].trim().to_string())
            .collect();
        assert_eq!(rust_fields, fields, "fields of {name} differ between the header and o3d-sys");
    }
}

#[test]
fn every_opaque_handle_is_declared() {
    for (_, text) in headers() {
        for line in text.lines() {
            let Some(rest) = line.trim().strip_prefix("typedef struct ") else { continue };
            if rest.contains('{') {
                continue;
            }
            // "o3d_kdtree o3d_kdtree_t;"
            let mut parts = rest.trim_end_matches(';').split_whitespace();
            let (tag, alias) = (parts.next().unwrap(), parts.next().unwrap());
            assert!(SOURCE.contains(&format!("pub struct {tag} {{")), "opaque {tag} not declared");
            assert!(SOURCE.contains(&format!("pub type {alias} = {tag};")), "alias {alias} not declared");
        }
    }
}
