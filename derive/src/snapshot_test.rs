//! The formatted copies of the expansions, `generated/expanded/<robot>.rs`, must be exactly what
//! the macro emits today for `generated/models/<robot>.json`, so that a reader (or a diff in
//! review) sees the code that is compiled.
//!
//! Run with `UPDATE_EXPANDED=1` to rewrite the copies instead of failing:
//! `UPDATE_EXPANDED=1 cargo test -p armdyn-derive --lib snapshot`.

use crate::emit::Variants;
use crate::expand;
use proc_macro2::Span;
use std::fs;
use std::path::{Path, PathBuf};

const HEADER: &str = "// @generated — do not edit; regenerate with: bash codegen/regenerate.sh\n";
const UPDATE_VAR: &str = "UPDATE_EXPANDED";
const UPDATE_COMMAND: &str = "UPDATE_EXPANDED=1 cargo test -p armdyn-derive --lib snapshot";

/// Stems of the files in `dir` with extension `ext`, sorted.
fn stems(dir: &Path, ext: &str) -> Vec<String> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .map(|entry| entry.path())
        .filter(|path| path.extension().is_some_and(|e| e == ext))
        .filter_map(|path| Some(path.file_stem()?.to_str()?.to_owned()))
        .collect();
    names.sort();
    names
}

/// The arguments of the `generated` crate's `robot_model!` call for `models/<name>.json`, as
/// written in `generated/src/models.rs`: `"models/<name>.json", f32, lanes` for a robot's main
/// model, `"models/<name>.json"` for the others (`None` if there is no call).
fn call_arguments(index: &str, name: &str) -> Option<String> {
    let plain = format!("\"models/{name}.json\"");
    let start = index.find(&format!("robot_model!({plain}"))? + "robot_model!(".len();
    let end = start + index[start..].find(')')?;
    Some(index[start..end].to_owned())
}

/// The variants a call's arguments ask for (`, f32`, `, lanes`).
fn variants_of(arguments: &str) -> Variants {
    let words: Vec<&str> = arguments.split(',').map(str::trim).collect();
    Variants {
        single: words.contains(&"f32"),
        lanes: words.contains(&"lanes"),
    }
}

/// The formatted expansion of `generated/models/<name>.json`, as the `generated` crate's
/// `robot_model!(arguments)` emits it.
fn expansion(generated: &Path, name: &str, arguments: &str) -> String {
    let relative = format!("models/{name}.json");
    let variants = variants_of(arguments);
    let location = expand::resolve(&relative, Some(generated.as_os_str().to_owned()), None)
        .unwrap_or_else(|message| panic!("{relative}: {message}"));
    let tokens = expand::expand_at(&location, Span::call_site(), variants)
        .unwrap_or_else(|error| panic!("{relative} does not expand: {error}"));
    let file: syn::File = syn::parse2(tokens)
        .unwrap_or_else(|error| panic!("expansion of {relative} is not a Rust file: {error}"));
    format!(
        "{HEADER}//\n// Expansion of `armdyn_derive::robot_model!({arguments})` in the `generated` crate,\n\
         // formatted with prettyplease. Not compiled: for reading and review.\n\n{}",
        prettyplease::unparse(&file)
    )
}

/// Writes through a temporary file and a rename, so a reader never sees half a file.
fn write_atomically(path: &Path, text: &str) {
    let mut temporary = PathBuf::from(path);
    temporary.set_extension("rs.tmp");
    fs::write(&temporary, text)
        .unwrap_or_else(|error| panic!("cannot write {}: {error}", temporary.display()));
    fs::rename(&temporary, path)
        .unwrap_or_else(|error| panic!("cannot rename to {}: {error}", path.display()));
}

#[test]
fn snapshot_of_expansions_is_current() {
    let generated = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated");
    let models = generated.join("models");
    let expanded = generated.join("expanded");
    let update = std::env::var_os(UPDATE_VAR).is_some_and(|value| value == "1");

    let index = fs::read_to_string(generated.join("src/models.rs"))
        .unwrap_or_else(|error| panic!("cannot read generated/src/models.rs: {error}"));
    let names = stems(&models, "json");
    let mut problems = Vec::new();
    for name in &names {
        let Some(arguments) = call_arguments(&index, name) else {
            problems.push(format!(
                "generated/src/models.rs does not expand generated/models/{name}.json"
            ));
            continue;
        };
        let text = expansion(&generated, name, &arguments);
        let target = expanded.join(format!("{name}.rs"));
        let current = fs::read_to_string(&target).ok();
        if current.as_deref() == Some(text.as_str()) {
            continue;
        }
        if update {
            fs::create_dir_all(&expanded)
                .unwrap_or_else(|error| panic!("cannot create {}: {error}", expanded.display()));
            write_atomically(&target, &text);
            eprintln!("wrote {}", target.display());
        } else if current.is_none() {
            problems.push(format!("generated/expanded/{name}.rs is missing"));
        } else {
            problems.push(format!(
                "generated/expanded/{name}.rs differs from the expansion of generated/models/{name}.json"
            ));
        }
    }
    for stale in stems(&expanded, "rs") {
        if names.contains(&stale) {
            continue;
        }
        let path = expanded.join(format!("{stale}.rs"));
        if update {
            fs::remove_file(&path)
                .unwrap_or_else(|error| panic!("cannot remove {}: {error}", path.display()));
            eprintln!("removed {}", path.display());
        } else {
            problems.push(format!(
                "generated/expanded/{stale}.rs has no generated/models/{stale}.json"
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "{}\nregenerate with `bash codegen/regenerate.sh`, or only the expanded copies with `{UPDATE_COMMAND}`",
        problems.join("\n")
    );
}
