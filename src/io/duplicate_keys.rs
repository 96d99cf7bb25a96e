//! Refuse a JSON object that repeats a key (policy, `docs/limits.md`):
//! `serde_json` keeps the last value silently, so `{"weights": [1, 1],
//! "weights": [1, -1]}` would read as whichever came last.
//!
//! One pass over text that `serde_json` has already accepted: strings are
//! skipped with their escapes, and a string followed by `:` is a key of the
//! innermost open object. Keys are compared after unescaping (`"a"` and
//! `"\u0061"` are the same key). Cost: linear in the text.

use crate::error::Error;
use std::collections::HashSet;

/// Check that no object of the (valid JSON) `text` repeats a key.
///
/// # Errors
///
/// [`Error::Format`] naming the repeated key.
pub(crate) fn check_no_duplicate_keys(text: &str) -> Result<(), Error> {
    let bytes = text.as_bytes();
    // One set of keys per open object; `None` for an open array.
    let mut open: Vec<Option<HashSet<String>>> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'{' => open.push(Some(HashSet::new())),
            b'[' => open.push(None),
            b'}' | b']' => {
                open.pop();
            }
            b'"' => {
                let end = string_end(bytes, i);
                if next_is_colon(bytes, end)
                    && let Some(Some(keys)) = open.last_mut()
                {
                    let key: String = serde_json::from_str(&text[i..end]).unwrap_or_default();
                    if !keys.insert(key.clone()) {
                        return Err(Error::Format(format!(
                            "the key {key:?} appears twice in one object"
                        )));
                    }
                }
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    Ok(())
}

/// The index just past the string literal opening at `start`.
fn string_end(bytes: &[u8], start: usize) -> usize {
    let mut i = start + 1;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => i += 2,
            b'"' => return i + 1,
            _ => i += 1,
        }
    }
    bytes.len()
}

fn next_is_colon(bytes: &[u8], from: usize) -> bool {
    bytes[from.min(bytes.len())..]
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        == Some(&b':')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_keys_are_found_at_any_depth() {
        assert!(check_no_duplicate_keys(r#"{"a": 1, "b": {"a": 2}, "c": ["a", "a"]}"#).is_ok());
        assert!(check_no_duplicate_keys(r#"{"a": 1, "a": 2}"#).is_err());
        assert!(check_no_duplicate_keys(r#"[{"x": {"k": 1, "k\"": 2, "k": 3}}]"#).is_err());
        assert!(check_no_duplicate_keys(r#"{"a": 1, "\u0061": 2}"#).is_err());
        assert!(check_no_duplicate_keys(r#"[{"a": 1}, {"a": 2}]"#).is_ok());
    }
}
