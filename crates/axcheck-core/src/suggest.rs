//! "Did you mean …?": the closest known name to a misspelt one, and the one way axcheck
//! words the suggestion in its messages.

/// The closest of `candidates` to `word` when it is close enough to be a likely typo
/// (an edit distance of at most 2, or a quarter of the candidate's length).
pub fn did_you_mean<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let word = word.to_ascii_lowercase();
    candidates
        .iter()
        .map(|c| (levenshtein(&word, c), *c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// ` (did you mean `x`?)` for a suggestion, nothing without one: appended to a message.
pub fn phrase(suggestion: Option<&str>) -> String {
    suggestion.map_or(String::new(), |s| format!(" (did you mean `{s}`?)"))
}

/// [`phrase`] of [`did_you_mean`]: the suggestion for `word` among `candidates`, if any.
pub fn hint(word: &str, candidates: &[&str]) -> String {
    phrase(did_you_mean(word, candidates))
}

/// Edit distance between two strings (characters, not bytes).
pub(crate) fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.chars().enumerate() {
        cur[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_names() {
        let c = ["deviation_um", "direction", "run"];
        assert_eq!(did_you_mean("deviaton_um", &c), Some("deviation_um"));
        assert_eq!(did_you_mean("dir", &c), None);
        assert_eq!(levenshtein("kitten", "sitting"), 3);
        assert_eq!(
            hint("tolerence", &["tolerances"]),
            " (did you mean `tolerances`?)"
        );
        assert_eq!(hint("zzz", &["tolerances"]), "");
    }
}
