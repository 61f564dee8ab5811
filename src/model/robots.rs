//! The robots of `robots/*.toml`, backed by the generated functions of `armdyn-generated`: one
//! type per entry of the generated registry (`armdyn_generated::for_each_robot!`), named after
//! the robot (`scara_mdh` -> `ScaraMdh`).
//!
//! Each type is zero-sized and converts between `nalgebra` types and the generated code's
//! fixed-size arrays; the conversions are copies of a few dozen `f64` that the optimiser
//! folds away. The types are made by [`robot_type!`](crate::robot_type), as a user's own
//! arm's is.

/// Defines the model type of every robot of the registry (`armdyn_generated::for_each_robot!`).
macro_rules! generated_robots {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        $(
            crate::robot_type!(
                #[doc = $doc]
                ///
                /// Zero-sized, backed by the generated functions of
                #[doc = concat!("`armdyn_generated::", stringify!($module), "`.")]
                pub struct $ty = armdyn_generated::$module, $n
            );
        )*
    };
}

armdyn_generated::for_each_robot!(generated_robots);
