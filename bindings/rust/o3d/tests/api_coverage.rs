//! Every function declared in `capi/include/o3d/*.h` is used by this crate's source (the same
//! check CI runs with grep over `bindings/rust/o3d/src`).
use std::path::PathBuf;

/// The headers o3d-sys read (its include folder, passed on as `DEP_O3D_INCLUDE_DIR`).
fn header_dir() -> PathBuf {
    PathBuf::from(env!("O3D_HEADER_DIR")).join("o3d")
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Whole-word occurrence of `name` in `text`.
fn mentions(text: &str, name: &str) -> bool {
    text.match_indices(name).any(|(pos, _)| {
        let before = text[..pos].chars().next_back();
        let after = text[pos + name.len()..].chars().next();
        !before.is_some_and(is_ident) && !after.is_some_and(is_ident)
    })
}

#[test]
fn every_c_api_function_is_called_by_the_safe_crate() {
    // src/generated/ holds the enums and options structs generated from the headers (their *_init calls).
    let src_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut source = String::new();
    for dir in [src_dir.clone(), src_dir.join("generated")] {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "rs") {
                source += &std::fs::read_to_string(&path).unwrap();
            }
        }
    }
    let mut names = Vec::new();
    for entry in std::fs::read_dir(header_dir()).unwrap_or_else(|e| panic!("{}: {e}", header_dir().display())) {
        let path = entry.unwrap().path();
        if path.extension().map_or(true, |e| e != "h") {
            continue;
        }
        for line in std::fs::read_to_string(&path).unwrap().lines() {
            let Some(decl) = line.trim_start().strip_prefix("O3D_API ") else { continue };
            let Some(paren) = decl.find('(') else { continue };
            let head = decl[..paren].trim_end();
            let start = head.rfind(|c: char| !is_ident(c)).map_or(0, |i| i + 1);
            names.push(head[start..].to_string());
        }
    }
    assert!(names.len() >= 85, "parsed only {} functions", names.len());
    let unused: Vec<_> = names.iter().filter(|n| !mentions(&source, n)).collect();
    assert!(unused.is_empty(), "C API functions not used by bindings/rust/o3d/src: {unused:?}");
}
