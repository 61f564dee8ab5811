//! Compile-time behaviour of `robot_model!`: bad model files give clear errors, a good one
//! compiles and computes the right numbers.
//!
//! trybuild compiles each case in a crate of its own under `target/tests/trybuild/`, so the
//! cases' relative fixture paths (`tests/ui/*.json`) are resolved against this crate's
//! directory through `ARMDYN_DERIVE_MANIFEST_DIR` (see the crate docs). Regenerate the
//! `.stderr` files with `TRYBUILD=overwrite cargo test -p armdyn-derive --test ui`.

#[test]
fn ui() {
    std::env::set_var("ARMDYN_DERIVE_MANIFEST_DIR", env!("CARGO_MANIFEST_DIR"));
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/fail_*.rs");
    cases.pass("tests/ui/pass_*.rs");
}
