//! Tests of `armdyn::contact`: the force sensor model, the reaction surface and the scene. A
//! file here tests the file of the same name in `src/contact/`.

mod scene;
mod sensor;
mod surface;
