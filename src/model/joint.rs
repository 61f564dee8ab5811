//! The kind of a joint.

/// How a joint moves its link; decides the unit of its coordinate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// Rotation about the joint's z axis; coordinate in rad, effort in N m.
    Revolute,
    /// Translation along the joint's z axis; coordinate in m, effort in N.
    Prismatic,
}

impl JointKind {
    /// `Prismatic` for `true`, `Revolute` for `false` (the generated `JOINT_IS_PRISMATIC`).
    ///
    /// ```
    /// use armdyn::model::JointKind;
    /// assert_eq!(JointKind::from_is_prismatic(true), JointKind::Prismatic);
    /// ```
    pub const fn from_is_prismatic(is_prismatic: bool) -> Self {
        if is_prismatic {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        }
    }

    /// The unit of the joint coordinate: `"rad"` or `"m"`.
    ///
    /// ```
    /// use armdyn::model::JointKind;
    /// assert_eq!(JointKind::Revolute.position_unit(), "rad");
    /// ```
    pub const fn position_unit(self) -> &'static str {
        match self {
            JointKind::Revolute => "rad",
            JointKind::Prismatic => "m",
        }
    }

    /// The unit of the joint's generalised force: `"N m"` or `"N"`.
    ///
    /// ```
    /// use armdyn::model::JointKind;
    /// assert_eq!(JointKind::Prismatic.effort_unit(), "N");
    /// ```
    pub const fn effort_unit(self) -> &'static str {
        match self {
            JointKind::Revolute => "N m",
            JointKind::Prismatic => "N",
        }
    }
}
