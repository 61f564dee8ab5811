// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// One module per description in robots/, in name order, and the registry of them all.

/// Franka Emika Panda, 7R, hand lumped in, fingers locked closed, from the URDF of example-robot-data (`robots/panda.toml`, 7 DOF, urdf).
pub mod panda {
    armdyn_runtime::robot_model!("models/panda.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/panda.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/panda_parametric.json");
    }
}

/// Planar 2R arm in a vertical plane (uniform rods), gravity along -y (`robots/planar2.toml`, 2 DOF, standard-dh).
pub mod planar2 {
    armdyn_runtime::robot_model!("models/planar2.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/planar2.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/planar2_parametric.json");
    }
}

/// PUMA 560, 6R, standard DH with the published inertial parameters (`robots/puma560.toml`, 6 DOF, standard-dh).
pub mod puma560 {
    armdyn_runtime::robot_model!("models/puma560.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/puma560.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/puma560_parametric.json");
    }
}

/// 4-DOF SCARA (RRPR) of the hybrid force/position thesis, Table 3.1 (`robots/scara.toml`, 4 DOF, standard-dh).
pub mod scara {
    armdyn_runtime::robot_model!("models/scara.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/scara.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/scara_parametric.json");
    }
}

/// The thesis SCARA of scara.toml, in modified (Craig) DH (`robots/scara_mdh.toml`, 4 DOF, modified-dh).
pub mod scara_mdh {
    armdyn_runtime::robot_model!("models/scara_mdh.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/scara_mdh.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/scara_mdh_parametric.json");
    }
}

/// Universal Robots UR5, 6R, from the URDF of example-robot-data (`robots/ur5.toml`, 6 DOF, urdf).
pub mod ur5 {
    armdyn_runtime::robot_model!("models/ur5.json", f32, lanes);

    /// The robot as a URDF (links in their joint frames, inertias about the COM),
    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.
    pub const URDF: &str = include_str!("../urdf/ur5.urdf");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        armdyn_runtime::robot_model!("models/ur5_parametric.json");
    }
}

/// The name of every generated robot (`robots/<name>.toml`), in name order.
pub const ROBOTS: [&str; 6] = ["panda", "planar2", "puma560", "scara", "scara_mdh", "ur5"];

/// The registry of generated robots: `for_each_robot!(callback)` expands to
/// `callback! { [] (module, Type, dof, "doc"), ... }` with one entry per robot in name order
/// (`module` in this crate, `Type` the name of its zero-sized model type); with more
/// tokens, `for_each_robot!(callback, tokens)`, they are passed inside the brackets.
/// Adding a robot is adding `robots/<name>.toml` and regenerating: everything that
/// expands this macro picks it up.
#[macro_export]
macro_rules! for_each_robot {
    ($callback:ident $(, $($args:tt)*)?) => {
        $callback! {
            [$($($args)*)?]
            (panda, Panda, 7, "Franka Emika Panda, 7R, hand lumped in, fingers locked closed, from the URDF of example-robot-data (`robots/panda.toml`, 7 DOF, urdf)")
            (planar2, Planar2, 2, "Planar 2R arm in a vertical plane (uniform rods), gravity along -y (`robots/planar2.toml`, 2 DOF, standard-dh)")
            (puma560, Puma560, 6, "PUMA 560, 6R, standard DH with the published inertial parameters (`robots/puma560.toml`, 6 DOF, standard-dh)")
            (scara, Scara, 4, "4-DOF SCARA (RRPR) of the hybrid force/position thesis, Table 3.1 (`robots/scara.toml`, 4 DOF, standard-dh)")
            (scara_mdh, ScaraMdh, 4, "The thesis SCARA of scara.toml, in modified (Craig) DH (`robots/scara_mdh.toml`, 4 DOF, modified-dh)")
            (ur5, Ur5, 6, "Universal Robots UR5, 6R, from the URDF of example-robot-data (`robots/ur5.toml`, 6 DOF, urdf)")
        }
    };
}
