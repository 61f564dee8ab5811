//! CasADi's own generated C for the robot models, behind a safe wrapper, to check and
//! benchmark the generated Rust (`armdyn_generated`) against it.
//!
//! The generator (`bash codegen/regenerate.sh`) writes, from the same expression graphs as
//! `generated/models/<robot>.json`, CasADi's C code generation of them to
//! `generated/casadi_c/<robot>.c`: functions `<robot>_<function>` and
//! `<robot>_parametric_<function>` with CasADi's standard C API. `build.rs` compiles all of
//! them at `-O3` (no `-ffast-math`; `-ffp-contract=off`) into this crate and declares them;
//! [`CFunction`] calls one with preallocated work arrays.
//!
//! Inputs are the dense vectors of the Rust arguments (`q`, `qd`, `qdd`, `params`); the single
//! output is the Rust output flattened row-major. Where CasADi's output is structurally sparse
//! (the regressors), [`CFunction::call`] expands the nonzeros in place into the dense output.
//!
//! # Checking and benchmarking
//!
//! From the workspace root:
//!
//! ```text
//! # C output == Rust output (to 1e-12 relative) for every function of scara and puma560
//! cargo test -p armdyn-casadi-c-bench --release
//! # ns per call of each Rust function and its C twin, in the same run
//! # (warm-up 1 s, measurement 2 s per benchmark unless overridden on the command line)
//! cargo bench -p armdyn-casadi-c-bench --bench rust_vs_c
//! # Markdown table from target/criterion/**/new/{benchmark,estimates}.json
//! cargo run -p armdyn-casadi-c-bench --bin bench_table --release
//! ```
//!
//! Filter the benchmark with a regex as usual, e.g.
//! `cargo bench -p armdyn-casadi-c-bench --bench rust_vs_c -- 'puma560/mass_matrix'`.
//!
//! # Example
//!
//! ```
//! use armdyn_casadi_c_bench::CFunction;
//!
//! let mut m = CFunction::new("scara_mass_matrix").unwrap();
//! let q = [0.1, 0.2, 0.05, 0.3];
//! let mut out = [0.0; 16];
//! m.call(&[&q], &mut out).unwrap();
//! let rust = armdyn_generated::scara::mass_matrix(&q);
//! assert!((out[1] - rust[0][1]).abs() <= 1e-12 * rust[0][1].abs());
//! ```

#![warn(missing_docs)]

use core::ffi::{c_double, c_int, c_longlong};
use core::fmt;
use core::ptr;

/// CasADi's `casadi_real` (the generated C keeps the default, `double`; checked by `build.rs`).
pub type CasadiReal = c_double;
/// CasADi's `casadi_int` (the generated C keeps the default, `long long int`).
pub type CasadiInt = c_longlong;

type EvalFn = unsafe extern "C" fn(
    *mut *const CasadiReal,
    *mut *mut CasadiReal,
    *mut CasadiInt,
    *mut CasadiReal,
    c_int,
) -> c_int;
type WorkFn =
    unsafe extern "C" fn(*mut CasadiInt, *mut CasadiInt, *mut CasadiInt, *mut CasadiInt) -> c_int;

/// The entry points of one generated C function. Only built by `build.rs`'s output, from
/// declarations it checked against the C prototypes, so the fields are private.
pub struct Symbols {
    name: &'static str,
    file: &'static str,
    eval: EvalFn,
    work: WorkFn,
    n_in: unsafe extern "C" fn() -> CasadiInt,
    n_out: unsafe extern "C" fn() -> CasadiInt,
    sparsity_in: unsafe extern "C" fn(CasadiInt) -> *const CasadiInt,
    sparsity_out: unsafe extern "C" fn(CasadiInt) -> *const CasadiInt,
    incref: unsafe extern "C" fn(),
    decref: unsafe extern "C" fn(),
    checkout: unsafe extern "C" fn() -> c_int,
    release: unsafe extern "C" fn(c_int),
}

mod ffi {
    use super::{c_int, CasadiInt, CasadiReal, Symbols};
    include!(concat!(env!("OUT_DIR"), "/casadi_functions.rs"));
}

impl Symbols {
    /// Every generated C function, in file then definition order.
    #[must_use]
    pub fn all() -> &'static [Symbols] {
        &ffi::FUNCTIONS
    }

    /// The function called `name` (e.g. `"puma560_parametric_gravity"`), if any.
    #[must_use]
    pub fn find(name: &str) -> Option<&'static Symbols> {
        ffi::FUNCTIONS.iter().find(|s| s.name == name)
    }

    /// The C function's name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// The stem of the C file defining it (the robot, e.g. `"scara"`).
    #[must_use]
    pub fn file(&self) -> &'static str {
        self.file
    }
}

impl fmt::Debug for Symbols {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Symbols")
            .field("name", &self.name)
            .field("file", &self.file)
            .finish()
    }
}

/// What went wrong constructing or calling a [`CFunction`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Error {
    /// No generated C function has this name.
    UnknownFunction(String),
    /// The function's interface is one this wrapper does not handle (or is malformed).
    Unsupported {
        /// The C function.
        function: &'static str,
        /// What is unsupported.
        reason: String,
    },
    /// [`CFunction::call`] got the wrong number of inputs.
    InputCount {
        /// The C function.
        function: &'static str,
        /// Inputs it takes.
        expected: usize,
        /// Inputs given.
        got: usize,
    },
    /// An input or the output slice has the wrong length.
    Length {
        /// The C function.
        function: &'static str,
        /// `"input 0"`, ..., or `"output"`.
        which: String,
        /// Length it needs.
        expected: usize,
        /// Length given.
        got: usize,
    },
    /// The C function returned a nonzero status.
    Status {
        /// The C function.
        function: &'static str,
        /// The status it returned.
        status: i32,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::UnknownFunction(name) => write!(f, "no generated C function `{name}`"),
            Self::Unsupported { function, reason } => write!(f, "`{function}`: {reason}"),
            Self::InputCount {
                function,
                expected,
                got,
            } => {
                write!(f, "`{function}` takes {expected} inputs, got {got}")
            }
            Self::Length {
                function,
                which,
                expected,
                got,
            } => {
                write!(
                    f,
                    "`{function}`: {which} needs length {expected}, got {got}"
                )
            }
            Self::Status { function, status } => write!(f, "`{function}` returned status {status}"),
        }
    }
}

impl std::error::Error for Error {}

/// A CasADi sparsity pattern in compressed form, read into owned data.
struct Sparsity {
    nrow: usize,
    ncol: usize,
    /// Linear (column-major) index of each nonzero, or `None` if dense.
    nonzeros: Option<Vec<usize>>,
}

impl Sparsity {
    /// Reads CasADi's compressed pattern at `sp`: `[nrow, ncol, 1]` if dense, else
    /// `[nrow, ncol, colind[0..=ncol], row[0..nnz]]` with `nnz = colind[ncol]`.
    fn read(function: &'static str, sp: *const CasadiInt) -> Result<Self, Error> {
        let bad = |reason: String| Error::Unsupported { function, reason };
        if sp.is_null() {
            return Err(bad("null sparsity pattern".into()));
        }
        // SAFETY: `sp` is non-null and comes from CasADi's `_sparsity_in/_out`, which return
        // a pointer to a `static const casadi_int[]` in compressed form; that form always
        // starts with at least the 3 entries `nrow, ncol, dense-flag-or-colind[0]`.
        let head = unsafe { core::slice::from_raw_parts(sp, 3) };
        let to_usize = |x: CasadiInt| usize::try_from(x).map_err(|_| bad(format!("entry {x}")));
        let (nrow, ncol) = (to_usize(head[0])?, to_usize(head[1])?);
        if head[2] == 1 {
            return Ok(Self {
                nrow,
                ncol,
                nonzeros: None,
            });
        }
        // Sparse: colind has ncol + 1 entries from index 2; read them, then nnz = colind[ncol].
        // SAFETY: as above; a non-dense compressed pattern holds `ncol + 1` column offsets
        // from index 2 (CasADi's `casadi_sparsify`/codegen layout).
        let colind = unsafe { core::slice::from_raw_parts(sp.add(2), ncol + 1) };
        let colind = colind
            .iter()
            .map(|&c| to_usize(c))
            .collect::<Result<Vec<_>, _>>()?;
        let nnz = colind[ncol];
        if colind[0] != 0
            || colind.windows(2).any(|w| w[0] > w[1])
            || nnz > nrow.saturating_mul(ncol)
        {
            return Err(bad(format!("malformed column offsets {colind:?}")));
        }
        // SAFETY: as above; the `nnz` row indices follow the column offsets.
        let rows = unsafe { core::slice::from_raw_parts(sp.add(3 + ncol), nnz) };
        let mut nonzeros = Vec::with_capacity(nnz);
        for col in 0..ncol {
            let rows = &rows[colind[col]..colind[col + 1]];
            let mut previous: Option<usize> = None;
            for &r in rows {
                let r = to_usize(r)?;
                if r >= nrow || previous.is_some_and(|p| p >= r) {
                    return Err(bad(format!("malformed row indices in column {col}")));
                }
                previous = Some(r);
                nonzeros.push(r + col * nrow);
            }
        }
        Ok(Self {
            nrow,
            ncol,
            nonzeros: Some(nonzeros),
        })
    }

    fn len(&self) -> usize {
        self.nrow * self.ncol
    }
}

/// Expands, in place, the `nnz` nonzeros of a sparse output (at the start of the dense output,
/// where the C writes them) to their dense positions, zeroing the structural zeros: runs of
/// consecutive nonzeros are moved with `copy_within`, last run first (each nonzero's dense
/// index is at least its position, so nothing is overwritten before it is moved), then the
/// gaps are zeroed.
#[derive(Debug)]
struct Expansion {
    nnz: usize,
    /// `(source start, destination start, length)`, by decreasing source.
    moves: Vec<(usize, usize, usize)>,
    /// `(start, end)` of each gap of structural zeros.
    zeros: Vec<(usize, usize)>,
}

impl Expansion {
    /// `index`: the strictly increasing dense index of each nonzero, all `< len`.
    fn new(index: &[usize], len: usize) -> Self {
        let mut moves = Vec::new();
        let mut zeros = Vec::new();
        let (mut k, mut next_dense) = (0, 0);
        while k < index.len() {
            let start = k;
            while k + 1 < index.len() && index[k + 1] == index[k] + 1 {
                k += 1;
            }
            k += 1;
            let dst = index[start];
            if dst > next_dense {
                zeros.push((next_dense, dst));
            }
            if dst != start {
                moves.push((start, dst, k - start));
            }
            next_dense = dst + (k - start);
        }
        if next_dense < len {
            zeros.push((next_dense, len));
        }
        moves.reverse();
        Self {
            nnz: index.len(),
            moves,
            zeros,
        }
    }

    #[inline]
    fn apply(&self, out: &mut [f64]) {
        for &(src, dst, len) in &self.moves {
            out.copy_within(src..src + len, dst);
        }
        for &(start, end) in &self.zeros {
            out[start..end].fill(0.0);
        }
    }
}

/// One generated C function, ready to call without allocating: dense inputs, one output.
///
/// Construction reads the function's `_n_in`, `_n_out`, `_work` and `_sparsity_in/_out`,
/// checks them and preallocates CasADi's `arg`, `res`, `iw` and `w` arrays; [`call`] checks
/// the slice lengths against them.
///
/// [`call`]: CFunction::call
pub struct CFunction {
    sym: &'static Symbols,
    mem: c_int,
    input_lens: Vec<usize>,
    output_len: usize,
    /// For a structurally sparse output, how to expand the nonzeros, which the C writes to
    /// the start of the output, in place.
    sparse_output: Option<Expansion>,
    /// CasADi's `arg` array (`sz_arg` entries, at least 1). [`CFunction::call`] sets the
    /// first `n_in` before calling the C; they are left stale afterwards (never dereferenced
    /// outside the call, and clearing them costs a `memset` per call), the rest stay null.
    arg: Vec<*const CasadiReal>,
    /// CasADi's `res` array (`sz_res` entries, at least 1); entry 0 is set like `arg`'s.
    res: Vec<*mut CasadiReal>,
    iw: Vec<CasadiInt>,
    w: Vec<CasadiReal>,
}

impl CFunction {
    /// The generated C function called `name`, e.g. `"scara_mass_matrix"`.
    ///
    /// # Errors
    ///
    /// [`Error::UnknownFunction`] if there is none, or see [`CFunction::from_symbols`].
    pub fn new(name: &str) -> Result<Self, Error> {
        let sym = Symbols::find(name).ok_or_else(|| Error::UnknownFunction(name.to_owned()))?;
        Self::from_symbols(sym)
    }

    /// Wraps `sym`, reading and checking its interface.
    ///
    /// # Errors
    ///
    /// [`Error::Unsupported`] if the function does not have exactly one output, has a
    /// sparse input, or reports malformed sizes; [`Error::Status`] if its `_work` fails.
    pub fn from_symbols(sym: &'static Symbols) -> Result<Self, Error> {
        let function = sym.name;
        let bad = |reason: String| Error::Unsupported { function, reason };
        // SAFETY: `_incref` takes no arguments and, per CasADi's API, must be called before
        // `_work`/`_checkout`; it is paired with `_decref` in `Drop` (or just below on error).
        unsafe { (sym.incref)() };
        let result = Self::configure(sym, &bad);
        if result.is_err() {
            // SAFETY: undoes the `_incref` above; no other call of this function is pending.
            unsafe { (sym.decref)() };
        }
        result
    }

    fn configure(sym: &'static Symbols, bad: &dyn Fn(String) -> Error) -> Result<Self, Error> {
        let function = sym.name;
        // SAFETY: `_n_in`/`_n_out` take no arguments and return a constant.
        let (n_in, n_out) = unsafe { ((sym.n_in)(), (sym.n_out)()) };
        let n_in = usize::try_from(n_in).map_err(|_| bad(format!("n_in = {n_in}")))?;
        if n_out != 1 {
            return Err(bad(format!("{n_out} outputs (only 1 is supported)")));
        }
        let mut sz = [0 as CasadiInt; 4];
        let [sz_arg, sz_res, sz_iw, sz_w] = &mut sz;
        // SAFETY: `_work` writes one `casadi_int` through each non-null pointer; all four
        // point to distinct live locals.
        let status = unsafe { (sym.work)(sz_arg, sz_res, sz_iw, sz_w) };
        if status != 0 {
            return Err(Error::Status { function, status });
        }
        let [sz_arg, sz_res, sz_iw, sz_w] =
            sz.map(|s| usize::try_from(s).map_err(|_| bad(format!("work size {s}"))));
        let (sz_arg, sz_res, sz_iw, sz_w) = (sz_arg?, sz_res?, sz_iw?, sz_w?);
        if sz_arg < n_in || sz_res < 1 {
            return Err(bad(format!(
                "sz_arg = {sz_arg} < n_in = {n_in} or sz_res = {sz_res} < 1"
            )));
        }

        let mut input_lens = Vec::with_capacity(n_in);
        for i in 0..n_in {
            // SAFETY: `i < n_in`, the range `_sparsity_in` answers for.
            let sp = Sparsity::read(function, unsafe { (sym.sparsity_in)(i as CasadiInt) })?;
            if sp.nonzeros.is_some() {
                return Err(bad(format!(
                    "input {i} is sparse (only dense inputs are supported)"
                )));
            }
            input_lens.push(sp.len());
        }
        // SAFETY: output 0 exists (`n_out == 1`).
        let out = Sparsity::read(function, unsafe { (sym.sparsity_out)(0) })?;
        let output_len = out.len();
        let sparse_output = out.nonzeros.map(|nz| Expansion::new(&nz, output_len));

        // SAFETY: `_checkout` takes no arguments; it returns a memory index (>= 0) to pass to
        // the function, released with `_release` in `Drop`.
        let mem = unsafe { (sym.checkout)() };
        if mem < 0 {
            return Err(bad(format!("checkout returned {mem}")));
        }
        Ok(Self {
            sym,
            mem,
            input_lens,
            output_len,
            sparse_output,
            arg: vec![ptr::null(); sz_arg.max(1)],
            res: vec![ptr::null_mut(); sz_res.max(1)],
            iw: vec![0; sz_iw.max(1)],
            w: vec![0.0; sz_w.max(1)],
        })
    }

    /// The C function's name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.sym.name
    }

    /// Length of each input.
    #[must_use]
    pub fn input_lens(&self) -> &[usize] {
        &self.input_lens
    }

    /// Length of the (dense) output.
    #[must_use]
    pub fn output_len(&self) -> usize {
        self.output_len
    }

    /// Number of structural nonzeros of the output (= [`CFunction::output_len`] if dense).
    #[must_use]
    pub fn output_nnz(&self) -> usize {
        self.sparse_output
            .as_ref()
            .map_or(self.output_len, |e| e.nnz)
    }

    /// Evaluates the function: `inputs[i]` is input `i` (dense), `out` receives the output
    /// (dense; structural zeros of a sparse output are written as `0.0`). Does not allocate.
    ///
    /// Data are in CasADi's storage order, column-major; the generator's inputs and outputs
    /// are all column vectors (the Rust output flattened row-major), so this is just the
    /// vector.
    ///
    /// # Errors
    ///
    /// [`Error::InputCount`]/[`Error::Length`] on a size mismatch (nothing is evaluated),
    /// [`Error::Status`] if the C function reports failure.
    #[inline]
    pub fn call(&mut self, inputs: &[&[f64]], out: &mut [f64]) -> Result<(), Error> {
        let function = self.sym.name;
        if inputs.len() != self.input_lens.len() {
            return Err(Error::InputCount {
                function,
                expected: self.input_lens.len(),
                got: inputs.len(),
            });
        }
        for (i, (x, &n)) in inputs.iter().zip(&self.input_lens).enumerate() {
            if x.len() != n {
                let which = format!("input {i}");
                return Err(Error::Length {
                    function,
                    which,
                    expected: n,
                    got: x.len(),
                });
            }
        }
        if out.len() != self.output_len {
            let (expected, got) = (self.output_len, out.len());
            return Err(Error::Length {
                function,
                which: "output".into(),
                expected,
                got,
            });
        }

        for (slot, x) in self.arg.iter_mut().zip(inputs) {
            *slot = x.as_ptr();
        }
        self.res[0] = out.as_mut_ptr();
        // SAFETY: the arguments follow CasADi's calling convention for this function, whose
        // sizes were read at construction: `arg` has `sz_arg` entries, the first `n_in`
        // pointing to live `&[f64]` inputs of exactly the dense input sizes (checked above),
        // the rest null (CasADi reads a null input as zeros); `res` has `sz_res` entries, the
        // first pointing to `out`, whose length (checked above) is the dense output size, at
        // least the `nnz` entries the C writes, the rest null. `iw`/`w` have at least
        // `sz_iw`/`sz_w` entries, exclusively borrowed. The inputs are shared borrows and the
        // output an exclusive borrow, so the C's writes alias nothing the inputs point to.
        // `mem` came from `_checkout`. The generated code is pure: it touches no other memory.
        let status = unsafe {
            (self.sym.eval)(
                self.arg.as_mut_ptr(),
                self.res.as_mut_ptr(),
                self.iw.as_mut_ptr(),
                self.w.as_mut_ptr(),
                self.mem,
            )
        };
        if status != 0 {
            return Err(Error::Status { function, status });
        }
        if let Some(expansion) = &self.sparse_output {
            expansion.apply(out);
        }
        Ok(())
    }
}

impl Drop for CFunction {
    fn drop(&mut self) {
        // SAFETY: `mem` was returned by this function's `_checkout` and is released once;
        // `_decref` pairs the `_incref` of construction.
        unsafe {
            (self.sym.release)(self.mem);
            (self.sym.decref)();
        }
    }
}

impl fmt::Debug for CFunction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CFunction")
            .field("name", &self.sym.name)
            .field("input_lens", &self.input_lens)
            .field("output_len", &self.output_len)
            .field("output_nnz", &self.output_nnz())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::Expansion;

    /// The in-place expansion equals a plain scatter, for every pattern of length <= 10.
    #[test]
    fn expansion_is_a_scatter() {
        let len = 10;
        for mask in 0u32..(1 << len) {
            let index: Vec<usize> = (0..len).filter(|i| mask & (1 << i) != 0).collect();
            let nonzeros: Vec<f64> = (0..index.len()).map(|k| k as f64 + 1.0).collect();
            let mut expected = vec![0.0; len];
            for (&i, &x) in index.iter().zip(&nonzeros) {
                expected[i] = x;
            }
            let mut out = vec![f64::NAN; len];
            out[..nonzeros.len()].copy_from_slice(&nonzeros);
            let e = Expansion::new(&index, len);
            e.apply(&mut out);
            assert_eq!(out, expected, "pattern {index:?}");
            assert_eq!(e.nnz, index.len());
        }
    }
}
