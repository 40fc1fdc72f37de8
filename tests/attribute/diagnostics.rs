//! Compile-time diagnostics: one file per mistake under `tests/ui/`, each
//! with the exact errors rustc prints (`tests/ui/*.stderr`). After a
//! deliberate change to a message, `TRYBUILD=overwrite cargo test --test
//! attribute diagnostics -- --include-ignored` rewrites them; review the
//! diff.
//!
//! Only `cargo check` runs on them (no case is built and run: that is
//! `every_item`), so this needs no second build of the library's code.
//! It takes minutes even so — a fresh build of the dependencies in
//! trybuild's own folder, then rustc once per case — and the messages
//! depend on the compiler's version: a long campaign, run by CI
//! (`-- --include-ignored`), not by the default `cargo test`.

#[test]
#[ignore = "a long campaign: rustc on every case of tests/ui (CI runs it)"]
fn diagnostics() {
    trybuild::TestCases::new().compile_fail("tests/ui/*.rs");
}
