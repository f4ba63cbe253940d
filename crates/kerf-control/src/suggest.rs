//! "Did you mean …?": the closest valid name to a mistyped one.

/// Edit distance (insertions, deletions, substitutions, and swaps of two
/// neighbours), case-insensitive.
pub fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.to_lowercase().chars().collect();
    let b: Vec<char> = b.to_lowercase().chars().collect();
    let w = b.len() + 1;
    let mut d = vec![0usize; (a.len() + 1) * w];
    for i in 0..=a.len() {
        for j in 0..=b.len() {
            d[i * w + j] = if i == 0 || j == 0 {
                i + j
            } else {
                let sub = d[(i - 1) * w + j - 1] + usize::from(a[i - 1] != b[j - 1]);
                let mut v = sub.min(d[(i - 1) * w + j] + 1).min(d[i * w + j - 1] + 1);
                if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                    v = v.min(d[(i - 2) * w + j - 2] + 1);
                }
                v
            };
        }
    }
    d[a.len() * w + b.len()]
}

/// The candidate closest to `name`, when it is close enough to be a slip
/// (at most a third of its length, and 3, edits away); failing that, the
/// one candidate that holds `name` (two characters or more) as a part
/// (`puma` for `puma-lathe`), when only one does.
pub fn closest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let candidates: Vec<&'a str> = candidates.into_iter().collect();
    let limit = (name.chars().count() / 3).clamp(1, 3);
    let near = candidates
        .iter()
        .map(|c| (distance(name, c), *c))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c);
    near.or_else(|| holding(name, &candidates))
}

/// The only candidate that contains `name` (case-insensitive, at least two
/// characters), None when none or several do.
fn holding<'a>(name: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let n = name.to_lowercase();
    if n.chars().count() < 2 {
        return None;
    }
    let mut hits = candidates.iter().filter(|c| c.to_lowercase().contains(&n));
    match (hits.next(), hits.next()) {
        (Some(c), None) => Some(*c),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_by_hand() {
        assert_eq!(distance("hx-mc", "hx-mc"), 0);
        assert_eq!(distance("hx-mx", "hx-mc"), 1);
        assert_eq!(distance("puma-lahte", "puma-lathe"), 1); // a swap
        assert_eq!(distance("puma", "puma-lathe"), 6);
        assert_eq!(distance("Dry_Run", "dry_run"), 0);
    }

    #[test]
    fn only_a_near_name_is_suggested() {
        let names = ["hx-mc", "puma-lathe", "hurco-lathe"];
        assert_eq!(closest("hx-mx", names), Some("hx-mc"));
        assert_eq!(closest("hurco-lath", names), Some("hurco-lathe"));
        // A part of one name only; a part of two is no suggestion.
        assert_eq!(closest("puma", names), Some("puma-lathe"));
        assert_eq!(closest("HURCO", names), Some("hurco-lathe"));
        assert_eq!(closest("lathe", names), None);
        assert_eq!(closest("x", ["hx-mc"]), None);
        assert_eq!(
            closest("dryrun", ["dry_run", "single_block"]),
            Some("dry_run")
        );
    }
}
