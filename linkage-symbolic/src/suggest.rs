//! "Did you mean ...?": the closest known name by edit distance.

/// The Levenshtein distance between two strings (on chars).
pub fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != cb));
            diagonal = above;
        }
    }
    row[b.len()]
}

/// The candidate closest to `name`, if it is close enough to be a likely typo
/// (at most a third of the name's length, and at least one edit, apart; a
/// different letter case counts as close).
pub fn closest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).max(1);
    candidates
        .into_iter()
        .filter(|c| *c != name)
        .map(|c| {
            let d = if c.eq_ignore_ascii_case(name) {
                0
            } else {
                distance(name, c)
            };
            (d, c)
        })
        .filter(|&(d, _)| d <= limit)
        // Ties go to the shorter name, then the first in alphabetical
        // order: the same suggestion whatever order the candidates come in
        // (a hash map's keys, say).
        .min_by_key(|&(d, c)| (d, c.len(), c))
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances() {
        assert_eq!(distance("theta3", "theta3"), 0);
        assert_eq!(distance("theta3", "theta4"), 1);
        assert_eq!(distance("thta3", "theta3"), 1);
        assert_eq!(distance("", "abc"), 3);
    }

    #[test]
    fn suggestions() {
        let known = ["theta2", "theta3", "l1", "l2", "PI"];
        assert_eq!(closest("thta3", known), Some("theta3"));
        assert_eq!(closest("pi", known), Some("PI"));
        assert_eq!(closest("omega", known), None);
        assert_eq!(closest("l3", ["l4", "l2"]), Some("l2"));
        assert_eq!(closest("l3", ["l2", "l4"]), Some("l2"));
    }
}
