//! "Did you mean …?": the closest known spelling to a mistaken one.
//!
//! (The equations' front end has its own, in `linkage-symbolic`, private
//! to that crate; this is the same rule.)

/// The edit distance between two strings (on characters): insertions,
/// deletions, substitutions and swaps of two neighbours ("stpes"), one
/// each (the optimal string alignment distance).
fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    // d[i][j]: the distance between a[..i] and b[..j].
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[a.len()][b.len()]
}

/// The candidate closest to `name`, if it is close enough to be a likely
/// typo (at most a third of the name's length, and at least one edit,
/// apart; a different letter case counts as close); of two as close, the
/// one that starts as the name does ("rat": `rate` rather than `at`), then
/// the one of the name's length ("mn": `mm` rather than `m`).
pub(super) fn closest<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).max(1);
    candidates
        .into_iter()
        .filter(|c| *c != name)
        .map(|c| {
            let d = if c.to_lowercase() == name.to_lowercase() {
                0
            } else {
                distance(name, c)
            };
            (d, c)
        })
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, c)| {
            let other_start = c.chars().next() != name.chars().next();
            let length = c.chars().count().abs_diff(name.chars().count());
            (d, other_start, length, c.len())
        })
        .map(|(_, c)| c)
}

/// "; did you mean `x`?" for the closest candidate, or nothing.
pub(super) fn did_you_mean<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> String {
    closest(name, candidates).map_or_else(String::new, |c| format!("; did you mean `{c}`?"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typos_are_caught_and_strangers_are_not() {
        let keys = ["from", "to", "steps", "rate", "acceleration", "at"];
        assert_eq!(closest("stpes", keys), Some("steps"));
        assert_eq!(closest("accel", keys), None);
        assert_eq!(closest("Rate", keys), Some("rate"));
        assert_eq!(closest("speed", keys), None);
        assert_eq!(closest("titel", ["title", "name"]), Some("title"));
        assert_eq!(closest("rat", keys), Some("rate"));
        assert_eq!(
            did_you_mean("mn", ["m", "mm", "min"]),
            "; did you mean `mm`?"
        );
        assert_eq!(distance("stpes", "steps"), 1);
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(did_you_mean("furlong", ["mm", "m"]), "");
    }
}
