//! `docs/registers.md`'s generated regions match the register map
//! (`golden_model::regmap::markdown`). `scripts/generate-docs` rewrites
//! them: it runs the ignored `write_registers_doc` below.

use golden_model::regmap::markdown::regenerate;
use std::path::PathBuf;

fn doc_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/registers.md")
}

#[test]
fn registers_doc_is_fresh() {
    let doc = std::fs::read_to_string(doc_path()).expect("docs/registers.md");
    let new = regenerate(&doc).expect("docs/registers.md's generated regions");
    assert!(
        new == doc,
        "docs/registers.md is stale: run scripts/generate-docs"
    );
}

/// Rewrites the regions (`scripts/generate-docs`).
#[test]
#[ignore = "writes docs/registers.md: run by scripts/generate-docs"]
fn write_registers_doc() {
    let path = doc_path();
    let doc = std::fs::read_to_string(&path).expect("docs/registers.md");
    let new = regenerate(&doc).expect("docs/registers.md's generated regions");
    if new != doc {
        std::fs::write(&path, new).expect("write docs/registers.md");
    }
}
