//! The chunking of long function bodies: more than [`CHUNK`] `let`s are cut into blocks that
//! hand on only the values read later, so that lexical scopes do not nest thousands deep
//! (which overflows rustc's stack when it emits debug info).

use crate::instruction::Op;
use crate::names::local;
use crate::scalar::Scalar;
use proc_macro2::{Ident, TokenStream};
use quote::quote;

/// Most `let`s in one block of an emitted function body; see [`chunked`].
const CHUNK: usize = 200;

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
/// `home[i]` is the statement that defines value `i` (see [`crate::sincos::sincos_pairs`]); a
/// value is handed on by the chunk of its statement.
pub(crate) fn chunked(
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expand::expand_str;
    use crate::parse;
    use proc_macro2::Span;

    const TINY: &str = include_str!("../tests/ui/pass_tiny.json");
    const LONG: &str = include_str!("../tests/ui/pass_long.json");

    /// The emitted functions of a model file: name, number of instructions, body.
    fn bodies(json: &str) -> Vec<(String, usize, syn::Block)> {
        let tokens =
            expand_str(json, Span::call_site(), crate::emit::Variants::NONE).expect("valid model");
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
}
