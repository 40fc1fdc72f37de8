//! Compile-time diagnostics: one file per mistake under `tests/ui/`, each
//! with the exact errors rustc prints (`tests/ui/*.stderr`). After a
//! deliberate change to a message, `TRYBUILD=overwrite cargo test --test ui`
//! rewrites them; review the diff.

#[test]
fn diagnostics() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
    // The uses of every generated item the tests of mistakes include, with
    // the types the attribute gives them when it has no mistake.
    cases.pass("tests/ui/every_item/no_mistake.rs");
}
