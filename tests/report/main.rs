//! Tests of `armdyn::report`: atomic writes, the data plots, decimation and the Markdown table.
//! A file here tests the file of the same name in `src/report/`; the plots, the CSV writer
//! and the viewer's parts are tested in their own files, through private items and the
//! crate's test runs, and the viewer in a real browser by the crate `tests/viewer.rs`.

mod atomic;
mod data_plots;
mod decimate;
mod table;
