//! The items of an expansion: the model's constants and, per function of the file, one
//! `pub fn` of one `let` per instruction (over `f64`, and again over `f32` in the optional
//! submodule), with its doc comment and its result as a nested array. Each body's `let`s go
//! through the sin/cos fusion ([`crate::sincos`]) and the chunking of long bodies
//! ([`crate::chunk`]).

use crate::chunk::chunked;
use crate::instruction::{Binary, Op, Unary};
use crate::names::local;
use crate::parse::{self, JointKind, Model};
use crate::scalar::Scalar;
use crate::sincos::sincos_pairs;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

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

/// The extra copies of the functions a `robot_model!` call asks for after the path.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Variants {
    /// `f32`: the submodule `f32`, in single precision.
    pub single: bool,
    /// `lanes`: the submodule `lanes`, every function generic over `L: ::armdyn_runtime::lanes::Lane`
    /// (several states per call, one per SIMD lane).
    pub lanes: bool,
}

#[cfg(test)]
impl Variants {
    /// Only the `f64` functions.
    pub(crate) const NONE: Self = Self {
        single: false,
        lanes: false,
    };
    /// The `f64` functions and the `f32` submodule.
    pub(crate) const SINGLE: Self = Self {
        single: true,
        lanes: false,
    };
}

/// The constants and the functions of `model` (`programs` are its decoded instructions), and
/// the submodules of `variants`.
pub(crate) fn emit(
    model: &Model,
    programs: &[Vec<Op>],
    variants: Variants,
) -> Result<TokenStream, String> {
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
    let task = robot.task.as_ref().map(|rows| {
        let len = Literal::usize_unsuffixed(rows.len());
        let rows = rows.iter().map(|&r| Literal::usize_unsuffixed(r));
        quote! {
            /// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end
            /// effector is controlled in (the description's `task`).
            pub const TASK_ROWS: [usize; #len] = [#(#rows),*];
        }
    });
    let count_len = Literal::usize_unsuffixed(model.functions.len());
    let counts = model.functions.iter().map(|f| {
        let fname = &f.name;
        let flops = Literal::u32_unsuffixed(f.counts.flops);
        let trig = Literal::u32_unsuffixed(f.counts.trig);
        quote!((#fname, #flops, #trig))
    });

    let functions = emit_functions(model, programs, Scalar::F64)?;
    let single = if variants.single {
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
    let lanes = if variants.lanes {
        let functions = emit_functions(model, programs, Scalar::Lane)?;
        quote! {
            /// The same functions over several states at once, generic over the lane type
            /// `L: ::armdyn_runtime::lanes::Lane` (`wide::f64x2`, `wide::f64x4`, or `f64`): input `i`
            /// of state `k` is lane `k` of `input[i]`, and so is each output element. The
            /// same instructions in the same order as the `f64` functions, each constant in
            /// every lane (`L::splat`); the arithmetic is IEEE `f64` lane by lane, the trig
            /// the trait's (`libm`'s for `f64`: bit for bit the scalar functions; `wide`'s
            /// vectorised `sin_cos` and `atan2` for the SIMD types, a few ulp from `libm`'s).
            /// For sweeps, planners and batches: several states per call keep the SIMD units
            /// busy. Same units as the parent module's.
            pub mod lanes {
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
        #task
        /// `(function, flops, trig)` for every function, in file order: floating-point
        /// operations (add, sub, mul, div, neg, sq, twice, inv, sqrt, fabs) and trig calls
        /// (sin, cos, atan2) in its body.
        pub const OPERATION_COUNTS: [(&str, u32, u32); #count_len] = [#(#counts),*];
        #(#functions)*
        #single
        #lanes
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
    let generics = if scalar == Scalar::Lane {
        quote!(<L: ::armdyn_runtime::lanes::Lane>)
    } else {
        TokenStream::new()
    };

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
        pub fn #name #generics(#(#inputs: &[#ty; #lengths]),*) -> #ret {
            #(#statements)*
            #body
        }
    })
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
                Unary::Sqrt => scalar.call("sqrt", &[x]),
                Unary::Sin => scalar.call("sin", &[x]),
                Unary::Cos => scalar.call("cos", &[x]),
                Unary::Fabs => scalar.call("fabs", &[x]),
            }
        }
        Op::Binary(op, x, y) => {
            let (x, y) = (local(*x), local(*y));
            match op {
                Binary::Add => quote!(#x + #y),
                Binary::Sub => quote!(#x - #y),
                Binary::Mul => quote!(#x * #y),
                Binary::Div => quote!(#x / #y),
                Binary::Atan2 => scalar.call("atan2", &[x, y]),
            }
        }
    };
    Ok(quote!(let #v: #ty = #value;))
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
    use crate::expand::expand_str;

    const TINY: &str = include_str!("../tests/ui/pass_tiny.json");

    #[test]
    fn tiny_expands() {
        let tokens = expand_str(TINY, Span::call_site(), Variants::NONE).expect("valid fixture");
        let text = tokens.to_string();
        assert!(text.contains("pub fn position (q : & [f64 ; 2]) -> [f64 ; 2]"));
        assert!(text.contains("pub fn mass_matrix (q : & [f64 ; 2]) -> [[f64 ; 2] ; 2]"));
        assert!(text.contains("-> [[[f64 ; 2] ; 2] ; 2]"));
        assert!(text.contains("let v1 : f64 = - 0.5_f64 ;"));
        assert!(text.contains("let v0 : f64 = 2.0_f64 ;"));
        assert!(text.contains("let v9 : f64 = 1e-3_f64 ;"));
        assert!(text.contains("[[v5 , v1] , [v1 , v6]]"));
        assert!(text.contains(":: armdyn_runtime :: libm :: atan2 (v0 , v1)"));
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
}
