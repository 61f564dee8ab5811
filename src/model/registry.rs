//! The registry of generated robots: look a robot up by name and call generic code with it.
//!
//! The list is the generator's (`armdyn_generated::ROBOTS`, `armdyn_generated::for_each_robot!`):
//! adding `robots/<name>.toml` and regenerating adds the robot here, to the command line, to
//! the tests and to the benchmarks.

/// The name of every generated robot, in name order.
pub const ROBOTS: &[&str] = &armdyn_generated::ROBOTS;

/// The one dispatcher from a robot's name to its type.
///
/// `with_robot_named!(name, |robot: R, N, module| body)` is `Some(body)` evaluated with `R` the
/// registry robot called `name` (its model type), `N` its joint count (a `const usize`),
/// `robot` its zero-sized model and `module` its generated module (`armdyn_generated::<name>`,
/// which holds its `URDF`), or `None` if the registry has no robot of that name. `body` is
/// expanded once per robot, with that robot's concrete type (any trait it implements can be
/// used); a `?` in it returns from the enclosing function. Every lookup by name (the
/// scenario's, the command line's, the Python package's) goes through it.
///
/// ```
/// use armdyn::model::RobotModel;
/// let dof = |name: &str| armdyn::with_robot_named!(name, |_robot: R, N, _module| N);
/// assert_eq!(dof("puma560"), Some(6));
/// assert_eq!(dof("kuka"), None);
/// let joint = armdyn::with_robot_named!("scara", |_robot: R, N, _module| R::JOINT_NAMES[0]);
/// assert_eq!(joint, Some("q1"));
/// ```
#[macro_export]
macro_rules! with_robot_named {
    ($name:expr, |$robot:ident: $r:ident, $n:ident, $module:ident| $body:expr) => {{
        #[allow(unused_imports)]
        use $crate::__with_robot_named_arms;
        $crate::__generated::for_each_robot!(
            __with_robot_named_arms,
            $name,
            $robot,
            $r,
            $n,
            $module,
            $body
        )
    }};
}

/// The arms of [`with_robot_named!`], one per robot of `armdyn_generated::for_each_robot!`.
#[doc(hidden)]
#[macro_export]
macro_rules! __with_robot_named_arms {
    (
        [$name:expr, $robot:ident, $r:ident, $n:ident, $m:ident, $body:expr]
        $(($module:ident, $ty:ident, $count:literal, $doc:literal))*
    ) => {
        match $name {
            $(stringify!($module) => {
                #[allow(unused_imports)]
                use $crate::__generated::$module as $m;
                #[allow(dead_code)]
                type $r = $crate::model::$ty;
                #[allow(dead_code)]
                const $n: usize = $count;
                let $robot = $crate::model::$ty;
                Some($body)
            })*
            _ => None,
        }
    };
}
