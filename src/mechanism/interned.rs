//! Names that live as long as the program: the analyses keep a
//! mechanism's names as `&'static str` (a compiled mechanism's are
//! constants), so a run-time mechanism's are interned here. Each distinct
//! name, and each distinct list of point names, is stored once for the
//! life of the process: a batch over millions of mechanisms that reuse
//! their names (`theta3`, `B`, …) stores each name once.

use std::collections::HashSet;
use std::sync::{Mutex, PoisonError};

static NAMES: Mutex<Option<HashSet<&'static str>>> = Mutex::new(None);
static LISTS: Mutex<Option<HashSet<&'static [&'static str]>>> = Mutex::new(None);

/// The one stored copy of `name`.
pub(crate) fn name(name: &str) -> &'static str {
    let mut names = NAMES.lock().unwrap_or_else(PoisonError::into_inner);
    let names = names.get_or_insert_with(HashSet::new);
    if let Some(&stored) = names.get(name) {
        return stored;
    }
    let stored: &'static str = Box::leak(name.to_owned().into_boxed_str());
    names.insert(stored);
    stored
}

/// The one stored copy of the list of `names` (each name interned).
pub(crate) fn list(names: &[&str]) -> &'static [&'static str] {
    let interned: Vec<&'static str> = names.iter().map(|n| name(n)).collect();
    let mut lists = LISTS.lock().unwrap_or_else(PoisonError::into_inner);
    let lists = lists.get_or_insert_with(HashSet::new);
    if let Some(&stored) = lists.get(interned.as_slice()) {
        return stored;
    }
    let stored: &'static [&'static str] = Box::leak(interned.into_boxed_slice());
    lists.insert(stored);
    stored
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_is_stored_once() {
        let a = name("theta3");
        let b = name(&String::from("theta3"));
        assert!(std::ptr::eq(a, b));
        assert_eq!(a, "theta3");
        assert_ne!(name("theta4"), a);
    }

    #[test]
    fn a_list_is_stored_once_and_keeps_its_order() {
        let a = list(&["B", "C"]);
        let b = list(&[&String::from("B"), "C"]);
        assert!(std::ptr::eq(a, b));
        assert_eq!(a, ["B", "C"]);
        assert_eq!(list(&["C", "B"]), ["C", "B"]);
        assert!(list(&[]).is_empty());
    }
}
