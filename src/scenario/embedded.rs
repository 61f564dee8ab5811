//! The thesis's trials as scenario files shipped with the binary (`scenarios/thesis-*.toml`),
//! so that `armdyn run hybrid` and the other trials need no file on disk.

use std::path::Path;

use super::error::ScenarioError;
use super::spec::Scenario;

/// Every built-in scenario: file name and text.
pub const BUILT_IN: [(&str, &str); 6] = [
    (
        "thesis-hybrid.toml",
        include_str!("../../scenarios/thesis-hybrid.toml"),
    ),
    (
        "thesis-hybrid-variable.toml",
        include_str!("../../scenarios/thesis-hybrid-variable.toml"),
    ),
    (
        "thesis-position.toml",
        include_str!("../../scenarios/thesis-position.toml"),
    ),
    (
        "thesis-contact.toml",
        include_str!("../../scenarios/thesis-contact.toml"),
    ),
    (
        "thesis-three-zone.toml",
        include_str!("../../scenarios/thesis-three-zone.toml"),
    ),
    (
        "three-zone.toml",
        include_str!("../../scenarios/three-zone.toml"),
    ),
];

/// The built-in scenario `name` (a file name of [`BUILT_IN`]).
///
/// # Errors
///
/// [`ScenarioError`] if there is no such scenario (or it does not parse: a build defect that
/// the tests catch).
pub fn built_in(name: &str) -> Result<Scenario, ScenarioError> {
    let (file, text) = BUILT_IN
        .iter()
        .find(|(f, _)| *f == name)
        .ok_or_else(|| ScenarioError {
            file: name.to_string(),
            key: String::new(),
            line: None,
            rule: format!(
                "no built-in scenario of that name; built in: {}",
                BUILT_IN
                    .iter()
                    .map(|(f, _)| *f)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })?;
    Scenario::parse(
        &format!("scenarios/{file} (built in)"),
        text,
        Path::new("scenarios"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_scenario_parses_and_matches_its_file() {
        for (name, text) in BUILT_IN {
            built_in(name).unwrap();
            let on_disk = std::fs::read_to_string(
                Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("scenarios")
                    .join(name),
            )
            .unwrap();
            assert_eq!(on_disk, text);
        }
        assert!(built_in("nope.toml")
            .unwrap_err()
            .to_string()
            .contains("thesis-hybrid.toml"));
    }
}
