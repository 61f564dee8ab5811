//! Phase 3: resolve the file, run the two other phases, and emit the items with `quote`.

use crate::parse::{self, JointKind, Model};
use crate::scalar::Scalar;
use crate::validate::{self, Binary, Op, Unary};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use syn::LitStr;

/// Environment variable that, when set, replaces `CARGO_MANIFEST_DIR` as the base of relative
/// model paths. Only the UI tests set it (trybuild compiles them in a crate of its own under
/// `target/`, whose manifest dir does not hold the fixtures).
pub(crate) const MANIFEST_DIR_OVERRIDE: &str = "SCARA_DERIVE_MANIFEST_DIR";

/// At most this many messages are reported; the rest are summarized in one line.
const MAX_ERRORS: usize = 50;

/// Most `let`s in one block of an emitted function body; see [`chunked`].
const CHUNK: usize = 200;

/// Where the model file is, and the argument of the `include_str!` that makes cargo rebuild
/// the calling crate when the file changes.
pub(crate) struct Location {
    pub path: PathBuf,
    pub include: TokenStream,
}

/// Expands `robot_model!("path")` (and, with `single`, the `f32` submodule of
/// `robot_model!("path", f32)`): resolves the path, reads, parses, validates and emits.
pub(crate) fn expand_file(path: &LitStr, single: bool) -> syn::Result<TokenStream> {
    let location = resolve(
        &path.value(),
        std::env::var_os("CARGO_MANIFEST_DIR"),
        std::env::var_os(MANIFEST_DIR_OVERRIDE),
    )
    .map_err(|message| syn::Error::new(path.span(), message))?;
    expand_at(&location, path.span(), single)
}

/// Resolves the path written in the macro call.
///
/// - An absolute path is used as is.
/// - A relative path is joined to `$SCARA_DERIVE_MANIFEST_DIR` if that is set, else to the
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

/// Reads and expands the file at `location` (with an `f32` submodule if `single`), adding the
/// rebuild dependency.
pub(crate) fn expand_at(location: &Location, span: Span, single: bool) -> syn::Result<TokenStream> {
    let json = parse::read(&location.path).map_err(|message| syn::Error::new(span, message))?;
    let items = expand_str(&json, span, single)?;
    let include = &location.include;
    Ok(quote! {
        #items
        const _: &str = include_str!(#include);
    })
}

/// Expands the text of a model file (with an `f32` submodule if `single`). Every error is
/// spanned on `span`.
pub(crate) fn expand_str(json: &str, span: Span, single: bool) -> syn::Result<TokenStream> {
    let model = parse::parse(json).map_err(|message| syn::Error::new(span, message))?;
    let programs = validate::validate(&model).map_err(|messages| combine(&messages, span))?;
    emit(&model, &programs, single).map_err(|message| syn::Error::new(span, message))
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

/// Lints allowed on the emitted functions: the code is machine-written (one `let` per
/// instruction, unused values, constants with all their digits, some close to `PI`) and read by
/// people through the formatted copy, so lints about its style do not apply.
fn allow_in_functions() -> TokenStream {
    quote! {
        #[allow(
            unused_variables,
            non_snake_case,
            clippy::all,
            clippy::pedantic,
            clippy::nursery
        )]
    }
}

/// Lints allowed on the emitted floating-point constants (limits such as `3.141592653589793`
/// would trip `clippy::approx_constant`).
fn allow_in_constants() -> TokenStream {
    quote! {
        #[allow(clippy::all, clippy::pedantic, clippy::nursery)]
    }
}

/// `#[doc = " line"]` for each line.
fn doc<I: IntoIterator<Item = S>, S: AsRef<str>>(lines: I) -> TokenStream {
    let attrs = lines.into_iter().map(|line| {
        let line = line.as_ref();
        let text = if line.is_empty() {
            String::new()
        } else {
            format!(" {line}")
        };
        quote!(#[doc = #text])
    });
    quote!(#(#attrs)*)
}

fn emit(model: &Model, programs: &[Vec<Op>], single: bool) -> Result<TokenStream, String> {
    let allow = allow_in_constants();
    let robot = &model.robot;
    let provenance = &model.provenance;
    let name = &robot.name;
    let description = &robot.description;
    let dof = Literal::usize_unsuffixed(robot.joints.len());
    let generator = &provenance.generator;
    let casadi = &provenance.casadi;
    let source = &provenance.source;
    let sha = &provenance.source_sha256;
    let joint_names = robot.joints.iter().map(|j| &j.name);
    let prismatic = robot.joints.iter().map(|j| j.kind == JointKind::Prismatic);
    let limits = robot
        .joints
        .iter()
        .map(|j| {
            let lower = float(j.lower)?;
            let upper = float(j.upper)?;
            Ok(quote!([#lower, #upper]))
        })
        .collect::<Result<Vec<_>, String>>()?;
    let efforts = robot
        .joints
        .iter()
        .map(|j| float(j.effort))
        .collect::<Result<Vec<_>, String>>()?;
    let gravity = robot
        .gravity
        .iter()
        .map(|&g| float(g))
        .collect::<Result<Vec<_>, String>>()?;
    let count_len = Literal::usize_unsuffixed(model.functions.len());
    let counts = model.functions.iter().map(|f| {
        let fname = &f.name;
        let flops = Literal::u32_unsuffixed(f.counts.flops);
        let trig = Literal::u32_unsuffixed(f.counts.trig);
        quote!((#fname, #flops, #trig))
    });

    let functions = emit_functions(model, programs, Scalar::F64)?;
    let single = if single {
        let functions = emit_functions(model, programs, Scalar::F32)?;
        quote! {
            /// The same functions in single precision (`f32`), for processors whose FPU has no
            /// `f64` (Cortex-M4F): every constant is the `f64` one rounded to the nearest
            /// `f32`, and `libm`'s `sinf`, `cosf`, `sqrtf`, `fabsf`, `atan2f` replace the
            /// `f64` calls. Same inputs, outputs and units as the parent module's.
            pub mod f32 {
                #(#functions)*
            }
        }
    } else {
        TokenStream::new()
    };

    Ok(quote! {
        /// Name of the robot (`robot.name` in the model file).
        pub const ROBOT_NAME: &str = #name;
        /// Description of the robot, from the model file.
        pub const DESCRIPTION: &str = #description;
        /// Degrees of freedom: the number of joints.
        pub const DOF: usize = #dof;
        /// Name and version of the generator that wrote the model file.
        pub const GENERATOR: &str = #generator;
        /// Version of CasADi the generator used.
        pub const CASADI_VERSION: &str = #casadi;
        /// Robot description file the model was generated from.
        pub const SOURCE: &str = #source;
        /// SHA-256 of the robot description file (64 hex digits).
        pub const SOURCE_SHA256: &str = #sha;
        /// Joint names, base to tip.
        pub const JOINT_NAMES: [&str; DOF] = [#(#joint_names),*];
        /// `true` for a prismatic joint (m, N), `false` for a revolute one (rad, N m).
        pub const JOINT_IS_PRISMATIC: [bool; DOF] = [#(#prismatic),*];
        /// Joint position limits `[lower, upper]`, rad or m.
        #allow
        pub const JOINT_LIMITS: [[f64; 2]; DOF] = [#(#limits),*];
        /// Actuator effort limits, N m (revolute) or N (prismatic).
        #allow
        pub const EFFORT_LIMITS: [f64; DOF] = [#(#efforts),*];
        /// Gravity vector in the base frame, m/s^2.
        #allow
        pub const GRAVITY: [f64; 3] = [#(#gravity),*];
        /// `(function, flops, trig)` for every function, in file order: floating-point
        /// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
        /// (sin, cos, atan2) in its body.
        pub const OPERATION_COUNTS: [(&str, u32, u32); #count_len] = [#(#counts),*];
        #(#functions)*
        #single
    })
}

/// Every function of the file over `scalar`.
fn emit_functions(
    model: &Model,
    programs: &[Vec<Op>],
    scalar: Scalar,
) -> Result<Vec<TokenStream>, String> {
    let allow = allow_in_functions();
    model
        .functions
        .iter()
        .zip(programs)
        .map(|(function, program)| emit_function(function, program, &allow, scalar))
        .collect()
}

fn emit_function(
    function: &parse::Function,
    program: &[Op],
    allow: &TokenStream,
    scalar: Scalar,
) -> Result<TokenStream, String> {
    let name = Ident::new(&function.name, Span::call_site());
    let inputs: Vec<Ident> = function
        .inputs
        .iter()
        .map(|input| Ident::new(&input.name, Span::call_site()))
        .collect();
    let lengths = function
        .inputs
        .iter()
        .map(|input| Literal::usize_unsuffixed(input.len));
    let shape = &function.output.shape;
    let ty = scalar.ty();
    let ret = shape.iter().rev().fold(quote!(#ty), |inner, &n| {
        let n = Literal::usize_unsuffixed(n);
        quote!([#inner; #n])
    });

    let docs = doc(function_doc(function, scalar));

    let mut lets = program
        .iter()
        .enumerate()
        .map(|(i, op)| statement(i, op, &inputs, scalar))
        .collect::<Result<Vec<_>, String>>()?;
    let home = sincos_pairs(program, &mut lets, scalar);
    let statements = chunked(program, &function.result, &home, lets, scalar)?;

    let result: Vec<Ident> = function.result.iter().map(|&i| local(i)).collect();
    let body = nest(&result, shape);

    Ok(quote! {
        #docs
        #[inline]
        #[must_use]
        #allow
        pub fn #name(#(#inputs: &[#ty; #lengths]),*) -> #ret {
            #(#statements)*
            #body
        }
    })
}

/// The local that holds the value of instruction `i`.
fn local(i: usize) -> Ident {
    format_ident!("v{}", i)
}

/// `let vI: f64 = ...;` (or `f32`) for instruction `i`.
fn statement(i: usize, op: &Op, inputs: &[Ident], scalar: Scalar) -> Result<TokenStream, String> {
    let v = local(i);
    let ty = scalar.ty();
    let value = match op {
        Op::Input { arg, elem } => {
            let input = inputs
                .get(*arg)
                .ok_or_else(|| format!("internal error: input {arg} missing"))?;
            let elem = Literal::usize_unsuffixed(*elem);
            quote!(#input[#elem])
        }
        Op::Const(text) => scalar.literal(text)?,
        Op::Unary(op, x) => {
            let x = local(*x);
            match op {
                Unary::Neg => quote!(-#x),
                Unary::Sq => quote!(#x * #x),
                Unary::Twice => {
                    let two = scalar.literal("2")?;
                    quote!(#two * #x)
                }
                Unary::Inv => {
                    let one = scalar.literal("1")?;
                    quote!(#one / #x)
                }
                Unary::Sqrt => call(scalar, "sqrt", &[x]),
                Unary::Sin => call(scalar, "sin", &[x]),
                Unary::Cos => call(scalar, "cos", &[x]),
                Unary::Fabs => call(scalar, "fabs", &[x]),
            }
        }
        Op::Binary(op, x, y) => {
            let (x, y) = (local(*x), local(*y));
            match op {
                Binary::Add => quote!(#x + #y),
                Binary::Sub => quote!(#x - #y),
                Binary::Mul => quote!(#x * #y),
                Binary::Div => quote!(#x / #y),
                Binary::Atan2 => call(scalar, "atan2", &[x, y]),
            }
        }
    };
    Ok(quote!(let #v: #ty = #value;))
}

/// `::libm::function(args)`, with the `f32` name (`sinf`, ...) for `f32`.
fn call(scalar: Scalar, function: &str, args: &[Ident]) -> TokenStream {
    let path = scalar.libm(function);
    quote!(#path(#(#args),*))
}

/// Fuses each `sin` and `cos` of the same operand into one `::libm::sincos` call (`sincosf`
/// for `f32`): the earlier of the two `let`s becomes
/// `let (vS, vC): (f64, f64) = ::libm::sincos(vX);` and the later one
/// is emitted as nothing. (libm's `sincos` is the same argument reduction and kernels as its
/// `sin` and `cos`, and returns bit-identical values; `tests::sincos_is_sin_and_cos` checks
/// it.) Returns `home`: `home[i]` is the instruction whose statement defines value `i` (`i`
/// itself, but the earlier partner for the later of a pair), for [`chunked`].
fn sincos_pairs(program: &[Op], lets: &mut [TokenStream], scalar: Scalar) -> Vec<usize> {
    let (ty, sincos) = (scalar.ty(), scalar.libm("sincos"));
    let mut home: Vec<usize> = (0..program.len()).collect();
    // operand -> (first sin, first cos); CasADi's instruction lists compute each at most once.
    let mut trig: std::collections::BTreeMap<usize, (Option<usize>, Option<usize>)> =
        std::collections::BTreeMap::new();
    for (i, op) in program.iter().enumerate() {
        match *op {
            Op::Unary(Unary::Sin, x) => {
                trig.entry(x).or_default().0.get_or_insert(i);
            }
            Op::Unary(Unary::Cos, x) => {
                trig.entry(x).or_default().1.get_or_insert(i);
            }
            _ => {}
        }
    }
    for (x, pair) in trig {
        let (Some(s), Some(c)) = pair else { continue };
        let (first, second) = (s.min(c), s.max(c));
        let (vs, vc, vx) = (local(s), local(c), local(x));
        lets[first] = quote!(let (#vs, #vc): (#ty, #ty) = #sincos(#vx););
        lets[second] = TokenStream::new();
        home[second] = first;
    }
    home
}

/// Groups the `let`s of a long body into blocks of at most [`CHUNK`] statements.
///
/// Every `let` opens a lexical scope nested in the previous one, and rustc's debuginfo
/// emission (LLVM `DwarfCompileUnit::createAndAddScopeChildren`) recurses once per level: a
/// flat body of a few thousand `let`s overflows rustc's stack whenever debug info is on. So a
/// body longer than [`CHUNK`] is cut into `ceil(n / CHUNK)` chunks of `ceil(n / chunks)`
/// statements (the last one may be shorter), each emitted as
///
/// ```text
/// let (vA, vB, ...) = {
///     let vI: f64 = ...;
///     ...
///     (vA, vB, ...)
/// };
/// ```
///
/// which hands on, by value, only the locals of the chunk that a later chunk or the result
/// reads (one of them: `let vA: f64 = { ...; vA };`; none: a bare block). The names and the
/// statements are those of the flat form, so the arithmetic, and its result bit for bit, is
/// unchanged; the optimizer sees through the tuples. Scopes then nest at most
/// `chunks + CHUNK + 1` deep instead of `n` (216 instead of 4287 for the PUMA 560 parametric
/// `coriolis_matrix`). A body of at most [`CHUNK`] statements is returned as is (the flat
/// form).
///
/// `home[i]` is the statement that defines value `i` (see [`sincos_pairs`]); a value is handed
/// on by the chunk of its statement.
fn chunked(
    program: &[Op],
    result: &[usize],
    home: &[usize],
    lets: Vec<TokenStream>,
    scalar: Scalar,
) -> Result<Vec<TokenStream>, String> {
    let ty = scalar.ty();
    let n = lets.len();
    if n <= CHUNK {
        return Ok(lets);
    }
    let size = n.div_ceil(n.div_ceil(CHUNK));
    // `last[i]`: the last chunk that reads value `i` (`usize::MAX` for the result), at least
    // the chunk that defines it.
    let mut last: Vec<usize> = home.iter().map(|&h| h / size).collect();
    let missing = |i: usize| format!("internal error: operand {i} out of range");
    for (j, op) in program.iter().enumerate() {
        let operands = match *op {
            Op::Input { .. } | Op::Const(_) => [None, None],
            Op::Unary(_, x) => [Some(x), None],
            Op::Binary(_, x, y) => [Some(x), Some(y)],
        };
        for x in operands.into_iter().flatten() {
            let slot = last.get_mut(x).ok_or_else(|| missing(x))?;
            *slot = (*slot).max(home[j] / size);
        }
    }
    for &r in result {
        *last.get_mut(r).ok_or_else(|| missing(r))? = usize::MAX;
    }
    // `handed[k]`: the values that chunk k defines and a later chunk or the result reads.
    let mut handed: Vec<Vec<Ident>> = vec![Vec::new(); n.div_ceil(size)];
    for (i, (&h, &read)) in home.iter().zip(&last).enumerate() {
        if read > h / size {
            handed[h / size].push(local(i));
        }
    }
    Ok(lets
        .chunks(size)
        .zip(handed)
        .map(|(lets, names)| match names.as_slice() {
            [] => quote!({ #(#lets)* }),
            [one] => quote!(let #one: #ty = { #(#lets)* #one };),
            _ => quote!(let (#(#names),*) = { #(#lets)* (#(#names),*) };),
        })
        .collect())
}

/// The doc comment of a generated function: the model's doc, then inputs, output and operation
/// count.
fn function_doc(function: &parse::Function, scalar: Scalar) -> Vec<String> {
    let ty = scalar.name();
    let shape = &function.output.shape;
    let mut lines: Vec<String> = function.doc.lines().map(str::to_owned).collect();
    lines.push(String::new());
    lines.push("# Inputs".to_owned());
    lines.push(String::new());
    if function.inputs.is_empty() {
        lines.push("None.".to_owned());
    }
    for input in &function.inputs {
        lines.push(format!(
            "- `{}: &[{ty}; {}]`: {}",
            input.name, input.len, input.doc
        ));
    }
    lines.push(String::new());
    lines.push("# Output".to_owned());
    lines.push(String::new());
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    let rust_type = shape
        .iter()
        .rev()
        .fold(ty.to_owned(), |inner, n| format!("[{inner}; {n}]"));
    lines.push(format!(
        "`{}: {rust_type}`{}: {}",
        function.output.name,
        if shape.len() > 1 {
            format!(" ({}, row-major)", dims.join(" x "))
        } else {
            String::new()
        },
        function.output.doc
    ));
    lines.push(String::new());
    lines.push(format!(
        "Operation count: {} floating-point operations, {} trig calls.",
        function.counts.flops, function.counts.trig
    ));
    lines
}

/// The row-major nested array literal of `values` for `shape` (validated: the length is the
/// product of the dimensions, all positive).
fn nest(values: &[Ident], shape: &[usize]) -> TokenStream {
    match shape {
        [] | [_] => quote!([#(#values),*]),
        [_, rest @ ..] => {
            let stride: usize = rest.iter().product();
            let rows = values.chunks(stride.max(1)).map(|chunk| nest(chunk, rest));
            quote!([#(#rows),*])
        }
    }
}

/// An `f64` literal for a finite value read as a JSON number (shortest round-trip text).
fn float(value: f64) -> Result<TokenStream, String> {
    Scalar::F64.literal(&format!("{value:?}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TINY: &str = include_str!("../tests/ui/pass_tiny.json");
    const LONG: &str = include_str!("../tests/ui/pass_long.json");

    fn errors(json: &str) -> Vec<String> {
        match expand_str(json, Span::call_site(), true) {
            Ok(_) => Vec::new(),
            Err(error) => error.into_iter().map(|e| e.to_string()).collect(),
        }
    }

    #[test]
    fn tiny_expands() {
        let tokens = expand_str(TINY, Span::call_site(), false).expect("valid fixture");
        let text = tokens.to_string();
        assert!(text.contains("pub fn position (q : & [f64 ; 2]) -> [f64 ; 2]"));
        assert!(text.contains("pub fn mass_matrix (q : & [f64 ; 2]) -> [[f64 ; 2] ; 2]"));
        assert!(text.contains("-> [[[f64 ; 2] ; 2] ; 2]"));
        assert!(text.contains("let v1 : f64 = - 0.5_f64 ;"));
        assert!(text.contains("let v0 : f64 = 2.0_f64 ;"));
        assert!(text.contains("let v9 : f64 = 1e-3_f64 ;"));
        assert!(text.contains("[[v5 , v1] , [v1 , v6]]"));
        assert!(text.contains(":: libm :: atan2 (v0 , v1)"));
    }

    /// The emitted functions of a model file: name, number of instructions, body.
    fn bodies(json: &str) -> Vec<(String, usize, syn::Block)> {
        let tokens = expand_str(json, Span::call_site(), false).expect("valid model");
        let file: syn::File = syn::parse2(tokens).expect("a Rust file");
        let model = parse::parse(json).expect("parses");
        let functions = file.items.into_iter().filter_map(|item| match item {
            syn::Item::Fn(f) => Some(f),
            _ => None,
        });
        functions
            .zip(&model.functions)
            .map(|(f, function)| {
                assert_eq!(f.sig.ident, function.name);
                (function.name.clone(), function.instructions.len(), *f.block)
            })
            .collect()
    }

    /// The block a `let` initializer or an expression statement is, if any.
    fn inner_block(stmt: &syn::Stmt) -> Option<&syn::Block> {
        let expr = match stmt {
            syn::Stmt::Local(local) => &local.init.as_ref()?.expr,
            syn::Stmt::Expr(expr, _) => expr,
            _ => return None,
        };
        match expr {
            syn::Expr::Block(block) => Some(&block.block),
            _ => None,
        }
    }

    /// How deep lexical scopes nest in `stmts`: every `let` opens one for the rest of its
    /// block, and every block one of its own.
    fn scope_depth(stmts: &[syn::Stmt]) -> usize {
        let (mut lets, mut deepest) = (0, 0);
        for stmt in stmts {
            if let Some(block) = inner_block(stmt) {
                deepest = deepest.max(lets + 1 + scope_depth(&block.stmts));
            }
            if matches!(stmt, syn::Stmt::Local(_)) {
                lets += 1;
            }
            deepest = deepest.max(lets);
        }
        deepest
    }

    /// The `vI` locals named in `tokens` (defined or read).
    fn locals(tokens: TokenStream, into: &mut std::collections::BTreeSet<usize>) {
        for tree in tokens {
            match tree {
                proc_macro2::TokenTree::Group(group) => locals(group.stream(), into),
                proc_macro2::TokenTree::Ident(ident) => {
                    let text = ident.to_string();
                    if let Some(i) = text.strip_prefix('v').and_then(|d| d.parse().ok()) {
                        into.insert(i);
                    }
                }
                _ => {}
            }
        }
    }

    /// The instructions whose values a `let` of instructions defines: `let vI: f64 = ...;` (one
    /// instruction), or `let (vS, vC): (f64, f64) = ::libm::sincos(vX);` (a sin and a cos).
    fn instruction(stmt: &syn::Stmt) -> Option<Vec<usize>> {
        let syn::Stmt::Local(local) = stmt else {
            return None;
        };
        let syn::Pat::Type(typed) = &local.pat else {
            return None;
        };
        if inner_block(stmt).is_some() {
            return None;
        }
        let index = |pat: &syn::Pat| -> Option<usize> {
            let syn::Pat::Ident(name) = pat else {
                return None;
            };
            name.ident.to_string().strip_prefix('v')?.parse().ok()
        };
        match &*typed.pat {
            syn::Pat::Tuple(pair) if pair.elems.len() == 2 => {
                pair.elems.iter().map(index).collect()
            }
            pat => Some(vec![index(pat)?]),
        }
    }

    /// The `let`s of one block, in instruction order (each at its first instruction), together
    /// defining each of `expected` exactly once.
    fn assert_in_order(name: &str, lets: &[syn::Stmt], expected: &[usize]) {
        let defined: Vec<Vec<usize>> = lets
            .iter()
            .map(|stmt| instruction(stmt).unwrap_or_else(|| panic!("{name}: not a let")))
            .collect();
        let firsts: Vec<usize> = defined.iter().map(|d| d[0].min(d[d.len() - 1])).collect();
        assert!(firsts.windows(2).all(|w| w[0] < w[1]), "{name}");
        let mut all: Vec<usize> = defined.concat();
        all.sort_unstable();
        assert_eq!(all, expected, "{name}");
    }

    #[test]
    fn short_bodies_stay_flat() {
        for json in [TINY, LONG] {
            for (name, n, body) in bodies(json) {
                if n > CHUNK {
                    continue;
                }
                let (result, lets) = body.stmts.split_last().expect("a result");
                assert_in_order(&name, lets, &(0..n).collect::<Vec<_>>());
                assert!(matches!(result, syn::Stmt::Expr(syn::Expr::Array(_), None)));
            }
        }
    }

    /// A sin and a cos of one operand are one `::libm::sincos` call, at the first of the two.
    #[test]
    fn sin_and_cos_of_one_operand_are_one_sincos() {
        let text = expand_str(TINY, Span::call_site(), true)
            .expect("valid")
            .to_string();
        let fused = "let (v3 , v2) : (f64 , f64) = :: libm :: sincos (v0) ;";
        assert!(text.contains(fused), "{text}");
        let fused = "let (v3 , v2) : (f32 , f32) = :: libm :: sincosf (v0) ;";
        assert!(text.contains(fused), "{text}");
        assert!(!text.contains(":: libm :: sinf (") && !text.contains(":: libm :: cosf ("));
        assert!(!text.contains(":: libm :: sin (") && !text.contains(":: libm :: cos ("));
        // The long fixture has sines without a cosine of the same operand: they stay `sin`.
        let text = expand_str(LONG, Span::call_site(), false)
            .expect("valid")
            .to_string();
        assert!(text.contains(":: libm :: sin (") && !text.contains(":: libm :: sincos ("));
    }

    /// libm's `sincos` is bit for bit its `sin` and `cos` (the same argument reduction and
    /// kernels; only the tiny-argument shortcut differs in its threshold, where both round to
    /// `x` and 1), so the fusion changes no result: over the ranges of joint angles, the
    /// thresholds, large arguments and special values.
    #[test]
    fn sincos_is_sin_and_cos() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let check = |x: f64| {
            let (s, c) = libm::sincos(x);
            assert_eq!(s.to_bits(), libm::sin(x).to_bits(), "sin {x:e}");
            assert_eq!(c.to_bits(), libm::cos(x).to_bits(), "cos {x:e}");
        };
        for x in [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            1e300,
            -1e300,
            f64::MAX,
        ] {
            check(x);
        }
        let (inf, nan) = (libm::sincos(f64::INFINITY), libm::sincos(f64::NAN));
        assert!(inf.0.is_nan() && inf.1.is_nan() && nan.0.is_nan() && nan.1.is_nan());
        for _ in 0..1_000_000 {
            let r = next();
            let unit = (r >> 11) as f64 / (1u64 << 53) as f64;
            check((unit - 0.5) * 20.0); // joint angles, with offsets
            check(f64::from_bits(next() & !(1 << 63)) * if r & 1 == 0 { 1.0 } else { -1.0 });
            // |x| around 2^-27 sqrt(2) .. 2^-26, where sin's and sincos's shortcuts differ
            check((1.0 + unit) * 2e-8 * if r & 2 == 0 { 1.0 } else { -1.0 });
        }
    }

    /// The same for `f32` (`sincosf` against `sinf` and `cosf`, emitted in the `f32` modules):
    /// four million arguments spread over [-16, 16] (where joint angles are), every `f32` in
    /// [1e-5, 1e-3] (the small-argument shortcuts), and a million random bit patterns.
    #[test]
    fn sincosf_is_sinf_and_cosf() {
        let check = |x: f32| {
            let (s, c) = libm::sincosf(x);
            assert_eq!(s.to_bits(), libm::sinf(x).to_bits(), "sinf {x:e}");
            assert_eq!(c.to_bits(), libm::cosf(x).to_bits(), "cosf {x:e}");
        };
        for i in 0..4_000_000u32 {
            check(-16.0 + 32.0 * (i as f32) / 4.0e6);
        }
        let mut x = 1e-5f32;
        while x <= 1e-3 {
            check(x);
            check(-x);
            x = x.next_up();
        }
        let mut state = 0x2545_f491_u32;
        for _ in 0..1_000_000 {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            let v = f32::from_bits(state);
            if v.is_finite() {
                check(v);
            }
        }
    }

    /// Every body longer than `CHUNK` (the long fixture and the whole PUMA 560 parametric
    /// model, whose 4287-instruction `coriolis_matrix` overflowed rustc's stack in the flat
    /// form): the instructions in order, in `ceil(n / CHUNK)` blocks of at most `CHUNK`, each
    /// handing on exactly the values read after it, and scopes nested at most
    /// `chunks + CHUNK + 1` deep.
    #[test]
    fn long_bodies_are_chunked() {
        let puma = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../generated/models/puma560_parametric.json");
        let puma = std::fs::read_to_string(&puma).expect("the PUMA 560 parametric model");
        let mut seen = 0;
        for json in [LONG, puma.as_str()] {
            for (name, n, body) in bodies(json) {
                if n <= CHUNK {
                    continue;
                }
                seen += 1;
                let chunks = n.div_ceil(CHUNK);
                let (result, blocks) = body.stmts.split_last().expect("a result");
                assert_eq!(blocks.len(), chunks, "{name}");
                let mut read_after = std::collections::BTreeSet::new();
                locals(quote!(#result), &mut read_after);
                let mut next = n;
                let mut defined_anywhere = std::collections::BTreeSet::new();
                for stmt in blocks.iter().rev() {
                    let block = inner_block(stmt).expect("a block");
                    let (defined, handed_on) = match block.stmts.last() {
                        Some(syn::Stmt::Expr(value, None)) => {
                            (&block.stmts[..block.stmts.len() - 1], Some(value))
                        }
                        _ => (&block.stmts[..], None),
                    };
                    assert!(defined.len() <= CHUNK, "{name}");
                    let first = instruction(&defined[0]).expect("a let");
                    let first = first[0].min(first[first.len() - 1]);
                    // This block's instructions: first..next, less the later of each sincos
                    // pair whose first is in an earlier block, plus those of this block's
                    // pairs that lie after next.
                    let mine: Vec<usize> = defined
                        .iter()
                        .flat_map(|stmt| instruction(stmt).expect("a let"))
                        .collect();
                    let mut sorted = mine.clone();
                    sorted.sort_unstable();
                    assert_in_order(&name, defined, &sorted);
                    assert!(mine.iter().all(|&i| i >= first), "{name}");
                    let mut exported = std::collections::BTreeSet::new();
                    locals(quote!(#handed_on), &mut exported);
                    let mut bound = std::collections::BTreeSet::new();
                    if let syn::Stmt::Local(local) = stmt {
                        let pat = &local.pat;
                        locals(quote!(#pat), &mut bound);
                    }
                    assert_eq!(bound, exported, "{name}");
                    let wanted: std::collections::BTreeSet<usize> = mine
                        .iter()
                        .copied()
                        .filter(|i| read_after.contains(i))
                        .collect();
                    for i in mine {
                        assert!(defined_anywhere.insert(i), "{name}: v{i} defined twice");
                    }
                    assert_eq!(exported, wanted, "{name}: values {first}..{next}");
                    locals(quote!(#(#defined)*), &mut read_after);
                    next = first;
                }
                assert_eq!(next, 0, "{name}");
                let all: Vec<usize> = defined_anywhere.iter().copied().collect();
                assert_eq!(all, (0..n).collect::<Vec<_>>(), "{name}");
                let depth = scope_depth(&body.stmts);
                assert!(depth <= chunks + CHUNK + 1, "{name}: depth {depth}");
            }
        }
        // The fixture's 2, and the PUMA's mass_matrix, coriolis_matrix, coriolis,
        // inverse_dynamics and forward_dynamics (gravity is shorter than CHUNK).
        assert_eq!(seen, 7);
    }

    #[test]
    fn literals() {
        let text = |s: &str| Scalar::F64.literal(s).map(|t| t.to_string());
        assert_eq!(text("2").as_deref(), Ok("2.0_f64"));
        assert_eq!(text("-1.5").as_deref(), Ok("- 1.5_f64"));
        assert_eq!(text("6.02e+23").as_deref(), Ok("6.02e+23_f64"));
        assert_eq!(
            float(-9.81).map(|t| t.to_string()).as_deref(),
            Ok("- 9.81_f64")
        );
        assert_eq!(
            float(1e-20).map(|t| t.to_string()).as_deref(),
            Ok("1e-20_f64")
        );
        assert_eq!(
            float(1000.0).map(|t| t.to_string()).as_deref(),
            Ok("1000.0_f64")
        );
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
