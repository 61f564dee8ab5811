//! How input text is quoted in error messages.

/// At most 40 characters of `s`, for messages (a longer text ends in `...`).
pub(crate) fn truncate(s: &str) -> String {
    const MAX: usize = 40;
    if s.chars().count() <= MAX {
        s.to_owned()
    } else {
        let head: String = s.chars().take(MAX).collect();
        format!("{head}...")
    }
}
