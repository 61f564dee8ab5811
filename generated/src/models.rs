// @generated — do not edit; regenerate with: bash codegen/regenerate.sh
//
// One module per description in robots/, in file-name order.

/// Planar 2R arm in a vertical plane (uniform rods), gravity along -y (`robots/planar2.toml`, 2 DOF, standard-dh).
pub mod planar2 {
    scara_derive::robot_model!("models/planar2.json");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        scara_derive::robot_model!("models/planar2_parametric.json");
    }
}

/// PUMA 560, 6R, standard DH with the published inertial parameters (`robots/puma560.toml`, 6 DOF, standard-dh).
pub mod puma560 {
    scara_derive::robot_model!("models/puma560.json");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        scara_derive::robot_model!("models/puma560_parametric.json");
    }
}

/// 4-DOF SCARA (RRPR) of the hybrid force/position thesis, Table 3.1 (`robots/scara.toml`, 4 DOF, standard-dh).
pub mod scara {
    scara_derive::robot_model!("models/scara.json");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        scara_derive::robot_model!("models/scara_parametric.json");
    }
}

/// The thesis SCARA of scara.toml, in modified (Craig) DH (`robots/scara_mdh.toml`, 4 DOF, modified-dh).
pub mod scara_mdh {
    scara_derive::robot_model!("models/scara_mdh.json");

    /// The same robot with its standard inertial parameters as an input `params`
    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the
    /// link frame origin), for identification and model-mismatch studies.
    pub mod parametric {
        scara_derive::robot_model!("models/scara_mdh_parametric.json");
    }
}
