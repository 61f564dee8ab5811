//! Phase 3: resolve the model path, run the phases (read and parse, validate, emit), and
//! gather every error into one compile error spanned on the path literal.

use crate::emit::{emit, Variants};
use crate::parse;
use crate::validate;
use proc_macro2::{Span, TokenStream};
use quote::quote;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use syn::LitStr;

/// Environment variable that, when set, replaces `CARGO_MANIFEST_DIR` as the base of relative
/// model paths. Only the UI tests set it (trybuild compiles them in a crate of its own under
/// `target/`, whose manifest dir does not hold the fixtures).
pub(crate) const MANIFEST_DIR_OVERRIDE: &str = "ARMDYN_DERIVE_MANIFEST_DIR";

/// At most this many messages are reported; the rest are summarized in one line.
const MAX_ERRORS: usize = 50;

/// Where the model file is, and the argument of the `include_str!` that makes cargo rebuild
/// the calling crate when the file changes.
pub(crate) struct Location {
    pub path: PathBuf,
    pub include: TokenStream,
}

/// Expands `robot_model!("path")` (and the submodules of `variants`, `robot_model!("path",
/// f32, lanes)`): resolves the path, reads, parses, validates and emits.
pub(crate) fn expand_file(path: &LitStr, variants: Variants) -> syn::Result<TokenStream> {
    let location = resolve(
        &path.value(),
        std::env::var_os("CARGO_MANIFEST_DIR"),
        std::env::var_os(MANIFEST_DIR_OVERRIDE),
    )
    .map_err(|message| syn::Error::new(path.span(), message))?;
    expand_at(&location, path.span(), variants)
}

/// Resolves the path written in the macro call.
///
/// - An absolute path is used as is.
/// - A relative path is joined to `$ARMDYN_DERIVE_MANIFEST_DIR` if that is set, else to the
///   calling crate's `$CARGO_MANIFEST_DIR`. In the usual last case the rebuild dependency is
///   written `concat!(env!("CARGO_MANIFEST_DIR"), "/", path)`, so the expansion does not
///   contain a machine-specific absolute path.
pub(crate) fn resolve(
    relative: &str,
    manifest_dir: Option<OsString>,
    override_dir: Option<OsString>,
) -> Result<Location, String> {
    if relative.is_empty() {
        return Err("empty model path: expected something like \"models/scara.json\"".to_owned());
    }
    let as_given = Path::new(relative);
    let absolute = |path: PathBuf| -> Result<Location, String> {
        let text = path
            .to_str()
            .ok_or_else(|| format!("model path `{}` is not valid UTF-8", path.display()))?;
        let include = quote!(#text);
        Ok(Location { path, include })
    };
    if as_given.is_absolute() {
        absolute(as_given.to_path_buf())
    } else if let Some(dir) = override_dir {
        absolute(PathBuf::from(dir).join(as_given))
    } else if let Some(dir) = manifest_dir {
        let path = PathBuf::from(dir).join(as_given);
        let include = quote!(concat!(env!("CARGO_MANIFEST_DIR"), "/", #relative));
        Ok(Location { path, include })
    } else {
        Err(format!(
            "cannot resolve `{relative}`: CARGO_MANIFEST_DIR is not set (build with cargo, or \
             give an absolute path)"
        ))
    }
}

/// Reads and expands the file at `location` (with the submodules of `variants`), adding the
/// rebuild dependency.
pub(crate) fn expand_at(
    location: &Location,
    span: Span,
    variants: Variants,
) -> syn::Result<TokenStream> {
    let json = parse::read(&location.path).map_err(|message| syn::Error::new(span, message))?;
    let items = expand_str(&json, span, variants)?;
    let include = &location.include;
    Ok(quote! {
        #items
        const _: &str = include_str!(#include);
    })
}

/// Expands the text of a model file (with the submodules of `variants`). Every error is
/// spanned on `span`.
pub(crate) fn expand_str(json: &str, span: Span, variants: Variants) -> syn::Result<TokenStream> {
    let model = parse::parse(json).map_err(|message| syn::Error::new(span, message))?;
    let programs = validate::validate(&model).map_err(|messages| combine(&messages, span))?;
    emit(&model, &programs, variants).map_err(|message| syn::Error::new(span, message))
}

/// One `syn::Error` holding every message (at most [`MAX_ERRORS`] of them).
fn combine(messages: &[String], span: Span) -> syn::Error {
    let mut shown = messages.iter().take(MAX_ERRORS);
    let mut error = syn::Error::new(
        span,
        shown.next().map_or("invalid model file", String::as_str),
    );
    for message in shown {
        error.combine(syn::Error::new(span, message));
    }
    if messages.len() > MAX_ERRORS {
        error.combine(syn::Error::new(
            span,
            format!("... and {} more errors", messages.len() - MAX_ERRORS),
        ));
    }
    error
}

#[cfg(test)]
mod tests {
    use super::*;

    const TINY: &str = include_str!("../tests/ui/pass_tiny.json");

    fn errors(json: &str) -> Vec<String> {
        match expand_str(json, Span::call_site(), Variants::SINGLE) {
            Ok(_) => Vec::new(),
            Err(error) => error.into_iter().map(|e| e.to_string()).collect(),
        }
    }

    #[test]
    fn every_rule_is_reported_at_once() {
        let many = errors(include_str!("../tests/ui/fail_many.json"));
        assert!(many.len() >= 7, "{many:#?}");
    }

    #[test]
    fn no_panic_on_any_prefix_or_edit() {
        let whole = TINY.trim_end();
        for end in (0..whole.len()).filter(|&end| whole.is_char_boundary(end)) {
            assert!(
                !errors(&whole[..end]).is_empty(),
                "prefix of {end} bytes accepted"
            );
        }
        let edits = [
            ("\"len\": 2", "\"len\": 0"),
            ("\"len\": 2", "\"len\": -1"),
            ("\"shape\": [2, 2]", "\"shape\": []"),
            (
                "\"shape\": [2, 2]",
                "\"shape\": [99999999999, 99999999999, 99999999999]",
            ),
            ("\"dof\": 2", "\"dof\": 18446744073709551615"),
            ("[\"input\", 0, 0]", "[\"input\", 18446744073709551615, -1]"),
            ("[\"input\", 0, 0]", "[]"),
            ("[\"input\", 0, 0]", "[7]"),
            ("[\"input\", 0, 0]", "{}"),
            ("[\"input\", 0, 0]", "[\"const\", 1.5]"),
            ("[\"input\", 0, 0]", "[\"input\", 0.5, 0]"),
            ("\"2\"", "\"1e99999999999999999999999\""),
            ("\"2\"", "\"\""),
            ("\"position\"", "\"r#position\""),
            ("-3.0", "NaN"),
            ("-3.0", "1e999"),
        ];
        for (from, to) in edits {
            assert!(TINY.contains(from), "{from}");
            let edited = TINY.replacen(from, to, 1);
            assert!(!errors(&edited).is_empty(), "{from} -> {to} accepted");
        }
        assert!(!errors("").is_empty());
        assert!(!errors("[]").is_empty());
        assert!(!errors("null").is_empty());
        assert!(!errors("{\"format\": 1}").is_empty());
    }

    #[test]
    fn paths() {
        let manifest = Some(OsString::from("/crate"));
        let normal = resolve("models/x.json", manifest.clone(), None).expect("resolves");
        assert_eq!(normal.path, Path::new("/crate/models/x.json"));
        assert_eq!(
            normal.include.to_string(),
            "concat ! (env ! (\"CARGO_MANIFEST_DIR\") , \"/\" , \"models/x.json\")"
        );
        let overridden = resolve("x.json", manifest.clone(), Some("/other".into())).expect("ok");
        assert_eq!(overridden.path, Path::new("/other/x.json"));
        let absolute = resolve("/abs/x.json", manifest, None).expect("resolves");
        assert_eq!(absolute.include.to_string(), "\"/abs/x.json\"");
        assert!(resolve("x.json", None, None).is_err());
        assert!(resolve("", Some("/crate".into()), None).is_err());
    }
}
