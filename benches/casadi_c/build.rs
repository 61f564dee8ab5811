//! Compiles CasADi's generated C (`generated/casadi_c/*.c`) into a static library and writes
//! the Rust declarations of its functions (`$OUT_DIR/casadi_functions.rs`).
//!
//! Compiler flags: `-O3` (the `opt-level = 3` of Cargo's `release`/`bench` profiles), no
//! `-ffast-math`, plus `-ffp-contract=off` so the C compiler cannot fuse `a*b + c` into an
//! FMA (rustc never does), keeping the C's rounding the same as the Rust's whatever `CFLAGS`
//! (e.g. `-march=native`) the environment adds, and no forced frame pointers (as rustc). `cc`
//! adds its usual `-fPIC -ffunction-sections -fdata-sections -m64 -march=x86-64` (the same
//! baseline CPU as rustc's default target) and `-g` when the profile has debuginfo.
//!
//! The declarations are checked here against the C: every exported evaluation function
//! `NAME(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem)`
//! must come with CasADi's companions (`NAME_work`, `NAME_n_in`, ...) with exactly the
//! prototypes the Rust side declares, and the file must leave `casadi_real`/`casadi_int` at
//! their defaults (`double`/`long long int`). Otherwise the build fails.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::{env, fs};

const EVAL_SUFFIX: &str =
    "(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){";
const EXPORT: &str = "CASADI_SYMBOL_EXPORT ";

/// `(suffix, C prototype with `{}` for the name, Rust signature after the name)` of each
/// companion function CasADi generates next to an evaluation function.
const COMPANIONS: &[(&str, &str, &str)] = &[
    (
        "_work",
        "int {}_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {",
        "(sz_arg: *mut CasadiInt, sz_res: *mut CasadiInt, sz_iw: *mut CasadiInt, sz_w: *mut CasadiInt) -> c_int",
    ),
    ("_n_in", "casadi_int {}_n_in(void) {", "() -> CasadiInt"),
    ("_n_out", "casadi_int {}_n_out(void) {", "() -> CasadiInt"),
    (
        "_sparsity_in",
        "const casadi_int* {}_sparsity_in(casadi_int i) {",
        "(i: CasadiInt) -> *const CasadiInt",
    ),
    (
        "_sparsity_out",
        "const casadi_int* {}_sparsity_out(casadi_int i) {",
        "(i: CasadiInt) -> *const CasadiInt",
    ),
    ("_incref", "void {}_incref(void) {", "()"),
    ("_decref", "void {}_decref(void) {", "()"),
    ("_checkout", "int {}_checkout(void) {", "() -> c_int"),
    ("_release", "void {}_release(int mem) {", "(mem: c_int)"),
];

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let dir = manifest.join("../../generated/casadi_c");
    println!("cargo:rerun-if-changed={}", dir.display());

    let mut files: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "c"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no C files in {}", dir.display());

    let mut decls = String::new();
    let mut table = String::new();
    let mut count = 0usize;
    for file in &files {
        println!("cargo:rerun-if-changed={}", file.display());
        let text = fs::read_to_string(file).unwrap();
        let stem = file.file_stem().unwrap().to_str().unwrap().to_owned();
        for default in [
            "#ifndef casadi_real\n#define casadi_real double\n#endif",
            "#ifndef casadi_int\n#define casadi_int long long int\n#endif",
        ] {
            assert!(
                text.contains(default),
                "{}: missing `{default}`",
                file.display()
            );
        }
        let lines: Vec<&str> = text.lines().collect();
        for line in &lines {
            let Some(rest) = line
                .strip_prefix(EXPORT)
                .and_then(|l| l.strip_prefix("int "))
            else {
                continue;
            };
            let Some(name) = rest.strip_suffix(EVAL_SUFFIX) else {
                continue;
            };
            for (suffix, c_proto, _) in COMPANIONS {
                let expected = format!("{EXPORT}{}", c_proto.replace("{}", name));
                assert!(
                    lines.iter().any(|l| l.starts_with(&expected)),
                    "{}: `{name}{suffix}` is not declared as `{expected}`",
                    file.display()
                );
            }
            writeln!(
                decls,
                "    fn {name}(arg: *mut *const CasadiReal, res: *mut *mut CasadiReal, \
                 iw: *mut CasadiInt, w: *mut CasadiReal, mem: c_int) -> c_int;"
            )
            .unwrap();
            for (suffix, _, rust) in COMPANIONS {
                writeln!(decls, "    fn {name}{suffix}{rust};").unwrap();
            }
            writeln!(
                table,
                "    Symbols {{ name: \"{name}\", file: \"{stem}\", eval: {name}, work: {name}_work, \
                 n_in: {name}_n_in, n_out: {name}_n_out, sparsity_in: {name}_sparsity_in, \
                 sparsity_out: {name}_sparsity_out, incref: {name}_incref, decref: {name}_decref, \
                 checkout: {name}_checkout, release: {name}_release }},"
            )
            .unwrap();
            count += 1;
        }
    }
    assert!(count > 0, "no CasADi functions found in {}", dir.display());

    let out = PathBuf::from(env::var("OUT_DIR").unwrap()).join("casadi_functions.rs");
    fs::write(
        &out,
        format!(
            "// @generated by build.rs from generated/casadi_c/*.c\n\
             extern \"C\" {{\n{decls}}}\n\n\
             /// Every function of `generated/casadi_c/*.c`, in file then definition order.\n\
             pub(crate) static FUNCTIONS: [Symbols; {count}] = [\n{table}];\n"
        ),
    )
    .unwrap();

    cc::Build::new()
        .files(&files)
        .opt_level(3)
        .flag_if_supported("-ffp-contract=off")
        // `cc` adds `-fno-omit-frame-pointer` when debuginfo is on (the workspace's bench
        // profile has `debug = 1`); rustc keeps omitting frame pointers, so the C should too.
        .force_frame_pointer(false)
        // CasADi's C has unused parameters etc. by design; its warnings are noise here.
        .warnings(false)
        .compile("casadi_models");
}
