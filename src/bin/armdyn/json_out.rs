//! JSON output for people and programs: objects indented one key per line, arrays of
//! numbers on one line, so a matrix prints one row per line.

use std::fmt::Write;

use serde_json::Value;

/// `value` as JSON: compact on one line, or indented with numeric rows kept on one line.
pub fn to_json(value: &Value, compact: bool) -> String {
    if compact {
        return value.to_string();
    }
    let mut out = String::new();
    write_indented(&mut out, value, 0);
    out
}

fn is_scalar(value: &Value) -> bool {
    !matches!(value, Value::Array(_) | Value::Object(_))
}

fn write_indented(out: &mut String, value: &Value, depth: usize) {
    let pad = "  ".repeat(depth + 1);
    let close = "  ".repeat(depth);
    match value {
        Value::Object(map) if !map.is_empty() => {
            out.push_str("{\n");
            for (i, (key, item)) in map.iter().enumerate() {
                let comma = if i + 1 < map.len() { "," } else { "" };
                // Writing to a String cannot fail.
                let _ = write!(out, "{pad}{}: ", Value::String(key.clone()));
                write_indented(out, item, depth + 1);
                out.push_str(comma);
                out.push('\n');
            }
            out.push_str(&close);
            out.push('}');
        }
        Value::Array(items) if !items.iter().all(is_scalar) => {
            out.push_str("[\n");
            for (i, item) in items.iter().enumerate() {
                let comma = if i + 1 < items.len() { "," } else { "" };
                out.push_str(&pad);
                write_indented(out, item, depth + 1);
                out.push_str(comma);
                out.push('\n');
            }
            out.push_str(&close);
            out.push(']');
        }
        Value::Array(items) => {
            let parts: Vec<String> = items.iter().map(Value::to_string).collect();
            let _ = write!(out, "[{}]", parts.join(", "));
        }
        scalar => out.push_str(&scalar.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn rows_stay_on_one_line_and_round_trip() {
        let value = json!({"robot": "x", "q": [1.0, -0.5], "m": [[1.0, 2.0], [3.0, 4.0]], "e": []});
        let text = to_json(&value, false);
        assert!(text.contains("\"q\": [1.0, -0.5],"), "{text}");
        assert!(text.contains("    [1.0, 2.0],\n    [3.0, 4.0]\n"), "{text}");
        assert_eq!(serde_json::from_str::<Value>(&text).unwrap(), value);
        assert_eq!(
            serde_json::from_str::<Value>(&to_json(&value, true)).unwrap(),
            value
        );
    }
}
