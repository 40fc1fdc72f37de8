use linkage::prelude::*;

#[linkage::linkage(u = [x], v = [t], closure = [x - t])]
pub enum Mechanism {
    FourBar,
}

fn main() {}
