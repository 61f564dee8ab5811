//! Tests of `armdyn::target`: orientation errors and interpolation. A file here tests the
//! file of the same name in `src/target/`.

mod orientation;
