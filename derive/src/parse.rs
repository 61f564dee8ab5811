//! Phase 1: read the model file and deserialize it into plain structs.
//!
//! Only the *shape* of the document is checked here (types, required keys, no unknown keys);
//! everything that needs more than one value at a time is in [`crate::validate`]. Instructions
//! are kept as raw JSON values so that every malformed one can be reported with its function
//! and index, instead of serde stopping at the first.

use serde::Deserialize;
use serde_json::Value;
use std::path::Path;

/// The only format this crate understands.
pub(crate) const FORMAT: &str = "armdyn-model-graph/1";

/// The whole model file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Model {
    /// Always [`FORMAT`].
    #[allow(dead_code)] // checked by `check_format` before the strict parse
    pub format: String,
    pub robot: Robot,
    pub provenance: Provenance,
    pub functions: Vec<Function>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Robot {
    pub name: String,
    pub description: String,
    pub dof: usize,
    pub joints: Vec<Joint>,
    pub gravity: [f64; 3],
    /// The rows of the geometric Jacobian (`vx vy vz wx wy wz`) the end effector is
    /// controlled in, increasing; absent in graphs without a task.
    #[serde(default)]
    pub task: Option<Vec<usize>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub lower: f64,
    pub upper: f64,
    pub effort: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(crate) enum JointKind {
    Revolute,
    Prismatic,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Provenance {
    pub generator: String,
    /// SHA-256 of the generator's modules and CasADi's version (what `regenerate.sh` compares
    /// to skip a robot whose graphs are current); not emitted, and absent from graphs written
    /// by hand.
    #[allow(dead_code)]
    #[serde(default)]
    pub generator_sha256: Option<String>,
    pub casadi: String,
    pub source: String,
    pub source_sha256: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Function {
    pub name: String,
    pub doc: String,
    pub inputs: Vec<Input>,
    pub output: Output,
    pub counts: Counts,
    /// Raw instructions, decoded by [`crate::validate`].
    pub instructions: Vec<Value>,
    pub result: Vec<usize>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Input {
    pub name: String,
    pub len: usize,
    pub doc: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Output {
    pub name: String,
    pub shape: Vec<usize>,
    pub doc: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Counts {
    pub flops: u32,
    pub trig: u32,
}

/// Just the version tag, read leniently before the strict parse so that a file of another
/// format version gets one clear message instead of a list of unknown keys.
#[derive(Deserialize)]
struct Header {
    format: Option<Value>,
}

/// Reads the model file as UTF-8 text.
pub(crate) fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path)
        .map_err(|err| format!("cannot read model file `{}`: {err}", path.display()))
}

/// Deserializes a model. Malformed JSON and structural errors (wrong type, missing or unknown
/// key) are reported with the JSON path and serde's line and column.
pub(crate) fn parse(json: &str) -> Result<Model, String> {
    // Syntax errors first: serde_json reports line and column.
    serde_json::from_str::<serde::de::IgnoredAny>(json)
        .map_err(|err| format!("malformed model file (not valid JSON): {err}"))?;
    let header: Header = serde_json::from_str(json)
        .map_err(|err| format!("invalid model file: the top level must be a JSON object: {err}"))?;
    match header.format {
        Some(Value::String(ref tag)) if tag == FORMAT => {}
        Some(other) => {
            return Err(format!(
                "unsupported model format {other}: this version of armdyn-derive reads `{FORMAT}`"
            ))
        }
        None => return Err(format!("missing key `format` (expected \"{FORMAT}\")")),
    }
    let de = &mut serde_json::Deserializer::from_str(json);
    serde_path_to_error::deserialize(de).map_err(|err| {
        let path = err.path().to_string();
        let inner = err.into_inner();
        if path == "." || path.is_empty() {
            format!("invalid model file: {inner}")
        } else {
            format!("invalid model file, at `{path}`: {inner}")
        }
    })
}
