//! The uses of every generated item that the tests of mistakes in
//! `tests/ui/` include compile and run with the types the attribute gives
//! them when it has no mistake (`tests/ui/every_item/no_mistake.rs`, built
//! here as a module of this test binary).

// `uses.rs` fills a struct that may have more fields (a case of a mistake
// adds one) with `..Default::default()`.
#[allow(clippy::needless_update)]
mod four_bar {
    include!("../ui/every_item/no_mistake.rs");

    pub fn run() {
        main();
    }
}

#[test]
fn every_item_compiles_and_runs() {
    four_bar::run();
}
