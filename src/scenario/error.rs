//! Errors of a scenario file: the file, the key (with its line where it can be found) and
//! the rule broken.

use toml::de::{DeTable, DeValue};

/// A scenario that cannot run, said before anything runs.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{file}{}: {}{rule}", line.map_or(String::new(), |l| format!(":{l}")), if key.is_empty() { String::new() } else { format!("`{key}`: ") })]
pub struct ScenarioError {
    /// The scenario file (as given).
    pub file: String,
    /// The key at fault, as a path (`surfaces[1].normal`; empty for the whole file).
    pub key: String,
    /// Its line (from 1), where known.
    pub line: Option<usize>,
    /// What is wrong.
    pub rule: String,
}

impl ScenarioError {
    /// An error at `key` of `file` whose text is `source` (to find the line in).
    pub fn at(file: &str, source: &str, key: &str, rule: impl Into<String>) -> Self {
        Self {
            file: file.to_string(),
            key: key.to_string(),
            line: line_of(source, key),
            rule: rule.into(),
        }
    }

    /// A parse error from the TOML reader (unknown key, wrong type, bad syntax), with the
    /// line it gives.
    pub fn parse(file: &str, source: &str, error: &toml::de::Error) -> Self {
        let line = error
            .span()
            .map(|s| source[..s.start.min(source.len())].matches('\n').count() + 1);
        let message = error.message().trim().to_string();
        let key = error
            .span()
            .and_then(|s| key_at(source, s.start))
            .unwrap_or_default();
        Self {
            file: file.to_string(),
            key,
            line,
            rule: message,
        }
    }
}

/// The dotted key of the table entry whose key or (non-table) value spans byte `at`.
fn key_at(source: &str, at: usize) -> Option<String> {
    let table = DeTable::parse(source).ok()?;
    find_in(table.get_ref(), at, String::new())
}

fn find_in(table: &DeTable<'_>, at: usize, prefix: String) -> Option<String> {
    let inside = |s: core::ops::Range<usize>| s.start <= at && at < s.end;
    for (k, v) in table {
        let mut path = prefix.clone();
        push(&mut path, k.get_ref());
        match v.get_ref() {
            DeValue::Table(t) => {
                if let Some(p) = find_in(t, at, path.clone()) {
                    return Some(p);
                }
                if inside(k.span()) {
                    return Some(path);
                }
            }
            DeValue::Array(items) => {
                for (i, item) in items.iter().enumerate() {
                    if let DeValue::Table(t) = item.get_ref() {
                        if let Some(p) = find_in(t, at, format!("{path}[{i}]")) {
                            return Some(p);
                        }
                    }
                }
                if inside(k.span()) || inside(v.span()) {
                    return Some(path);
                }
            }
            _ => {
                if inside(k.span()) || inside(v.span()) {
                    return Some(path);
                }
            }
        }
    }
    None
}

fn push(path: &mut String, key: &str) {
    if !path.is_empty() {
        path.push('.');
    }
    path.push_str(key);
}

/// The line (from 1) of `key` (`a.b[2].c`) in `source`, if the file parses and has it.
#[must_use]
pub fn line_of(source: &str, key: &str) -> Option<usize> {
    let table = DeTable::parse(source).ok()?;
    let mut current = table.get_ref();
    let mut span = None;
    let parts: Vec<&str> = key.split('.').filter(|p| !p.is_empty()).collect();
    for (depth, part) in parts.iter().enumerate() {
        let (name, index) = match part.split_once('[') {
            Some((n, rest)) => (n, rest.trim_end_matches(']').parse::<usize>().ok()),
            None => (*part, None),
        };
        let Some((k, v)) = current.iter().find(|(k, _)| k.get_ref().as_ref() == name) else {
            // A missing key: the line of the deepest table that is there.
            break;
        };
        span = Some(k.span());
        let mut value = v;
        if let Some(i) = index {
            if let DeValue::Array(items) = v.get_ref() {
                value = items.get(i)?;
                span = Some(value.span());
            }
        }
        if depth + 1 < parts.len() {
            match value.get_ref() {
                DeValue::Table(t) => current = t,
                _ => break,
            }
        }
    }
    span.map(|s| source[..s.start.min(source.len())].matches('\n').count() + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "format = 1\n\n[reference]\nkind = \"x\"\n\n[[surfaces]]\nkind = \"plane\"\n\n[[surfaces]]\nkind = \"sphere\"\nradius = 1.0\n";

    #[test]
    fn finds_lines_of_nested_keys() {
        assert_eq!(line_of(TEXT, "format"), Some(1));
        assert_eq!(line_of(TEXT, "reference.kind"), Some(4));
        assert_eq!(line_of(TEXT, "surfaces[1].radius"), Some(11));
        assert_eq!(line_of(TEXT, "surfaces[0].kind"), Some(7));
        assert_eq!(line_of(TEXT, "nothing.here"), None);
        // A missing key is placed at its table.
        assert_eq!(line_of(TEXT, "surfaces[1].normal"), Some(9));
    }

    #[test]
    fn formats_file_line_key_rule() {
        let e = ScenarioError::at("a.toml", TEXT, "surfaces[1].radius", "must be > 0 m");
        assert_eq!(
            e.to_string(),
            "a.toml:11: `surfaces[1].radius`: must be > 0 m"
        );
        assert_eq!(
            key_at(TEXT, TEXT.find("1.0").unwrap()).as_deref(),
            Some("surfaces[1].radius")
        );
    }
}
