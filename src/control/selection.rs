//! When the hybrid controller controls force: at a fixed time (the thesis's switch at 2 s,
//! eq. 5.5-5.6) or on detected contact, with an approach, a debounce, a force ramp and a
//! return to the approach when contact is lost (thesis Chapter 6: "switch on contact").

/// Settings of contact-triggered switching.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactSwitch {
    /// Measured normal push that counts as contact, N (> 0).
    pub threshold_n: f64,
    /// How long the push must stay at or above the threshold before the switch, s.
    pub debounce_s: f64,
    /// Time over which the force reference ramps from the measured force to its target, s.
    pub ramp_s: f64,
    /// Speed of the approach along the expected inward normal once the reference has
    /// reached the expected surface without contact, m/s (> 0).
    pub approach_speed_m_s: f64,
    /// How long the push may stay below half the threshold before force control gives up
    /// and the approach resumes, s.
    pub loss_s: f64,
}

impl ContactSwitch {
    /// Defaults for a sensor with white noise of `noise_std_n` (N, 1 sigma per axis) and a
    /// bias of `bias_n` (N): threshold `max(2 N, |bias| + 6 sigma)` (a false trigger needs a
    /// 6-sigma run over the whole debounce), debounce 3 ms, ramp 50 ms, approach at
    /// 20 mm/s, loss after 20 ms.
    #[must_use]
    pub fn for_sensor(noise_std_n: f64, bias_n: f64) -> Self {
        Self {
            threshold_n: (bias_n.abs() + 6.0 * noise_std_n).max(2.0),
            debounce_s: 0.003,
            ramp_s: 0.05,
            approach_speed_m_s: 0.02,
            loss_s: 0.02,
        }
    }
}

/// The selection policy: which instants are force controlled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SelectionPolicy {
    /// Position control before `switch_s` (s), force control along the normal from then on.
    Time {
        /// Switch time, s.
        switch_s: f64,
    },
    /// Force control from detected contact on (see [`ContactSwitch`]).
    Contact(ContactSwitch),
}

/// Phase of a contact-triggered run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Phase {
    /// Following the reference in position everywhere.
    Free,
    /// Past the expected surface without contact: moving along the inward normal at the
    /// approach speed, `offset_m` beyond the reference at time `since_s` (the offset grows
    /// from there).
    Approach {
        /// When this approach started, s.
        since_s: f64,
        /// Offset along the inward normal at `since_s`, m.
        offset_m: f64,
    },
    /// Force controlled since `since_s`; the force reference ramps from `from_n` (the signed
    /// normal force measured at the switch).
    Force {
        /// Switch time, s.
        since_s: f64,
        /// Signed normal force at the switch, N.
        from_n: f64,
    },
}

/// The switching state machine (no allocation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModeSelector {
    policy: SelectionPolicy,
    phase: Phase,
    above_s: f64,
    below_s: f64,
    switches: u32,
}

/// What the selector decided for one step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Decision {
    /// Position control; the target is moved `offset_m` along the inward normal, at
    /// `offset_rate_m_s`.
    Position {
        /// Offset into the surface, m.
        offset_m: f64,
        /// Its rate, m/s.
        offset_rate_m_s: f64,
    },
    /// Force control; `just_switched` on the first step, when the force integral is to be
    /// initialised; `ramp` in `[0, 1]`: share of the way from the force at the switch to the
    /// reference.
    Force {
        /// First step of force control.
        just_switched: bool,
        /// Ramp progress.
        ramp: f64,
        /// Signed normal force at the switch, N.
        from_n: f64,
    },
}

/// The force reference along the ramp of a switch: `target_n` once `ramp` (0 at the switch, 1
/// at its end) reaches 1, before that `from_n + (target_n - from_n) ramp`, N.
#[must_use]
pub fn ramped_force(from_n: f64, target_n: f64, ramp: f64) -> f64 {
    if ramp >= 1.0 {
        target_n
    } else {
        from_n + (target_n - from_n) * ramp
    }
}

impl ModeSelector {
    /// [`step`](Self::step) for a force `f_n` (N, along the outward normal of `frame`; negative:
    /// pressing), with the gaps of the reference position `reference` and the tool position
    /// `tool` above `frame`'s surface, m, which only contact switching looks at.
    pub fn step_on(
        &mut self,
        frame: &super::task_frame::TaskFrame,
        t: f64,
        dt: f64,
        f_n: f64,
        reference: &nalgebra::Vector3<f64>,
        tool: &nalgebra::Vector3<f64>,
    ) -> Decision {
        let (ref_gap, tool_gap) = match self.policy {
            SelectionPolicy::Contact(_) => (
                frame.signed_distance(reference),
                frame.signed_distance(tool),
            ),
            SelectionPolicy::Time { .. } => (None, None),
        };
        self.step(t, dt, -f_n, f_n, ref_gap, tool_gap)
    }

    /// A selector in its initial phase.
    #[must_use]
    pub fn new(policy: SelectionPolicy) -> Self {
        Self {
            policy,
            phase: Phase::Free,
            above_s: 0.0,
            below_s: 0.0,
            switches: 0,
        }
    }

    /// The policy.
    #[must_use]
    pub fn policy(&self) -> &SelectionPolicy {
        &self.policy
    }

    /// The current phase.
    #[must_use]
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// Back to the initial phase.
    pub fn reset(&mut self) {
        *self = Self::new(self.policy);
    }

    /// One step at time `t` (s) after `dt`: `push_n` is the measured push along the inward
    /// normal (N, positive pressing), `reference_gap_m` the reference's signed distance from
    /// the expected surface (`None` if unknown), `tool_gap_m` the tool's.
    pub fn step(
        &mut self,
        t: f64,
        dt: f64,
        push_n: f64,
        signed_force_n: f64,
        reference_gap_m: Option<f64>,
        tool_gap_m: Option<f64>,
    ) -> Decision {
        let c = match self.policy {
            SelectionPolicy::Time { switch_s } => {
                return if t < switch_s {
                    Decision::Position {
                        offset_m: 0.0,
                        offset_rate_m_s: 0.0,
                    }
                } else {
                    Decision::Force {
                        just_switched: false,
                        ramp: 1.0,
                        from_n: 0.0,
                    }
                };
            }
            SelectionPolicy::Contact(c) => c,
        };
        match self.phase {
            Phase::Free | Phase::Approach { .. } => {
                self.above_s = if push_n >= c.threshold_n {
                    self.above_s + dt
                } else {
                    0.0
                };
                if self.above_s >= c.debounce_s - 1e-12 {
                    self.phase = Phase::Force {
                        since_s: t,
                        from_n: signed_force_n,
                    };
                    self.below_s = 0.0;
                    self.switches += 1;
                    return Decision::Force {
                        just_switched: true,
                        ramp: 0.0,
                        from_n: signed_force_n,
                    };
                }
                if self.phase == Phase::Free && reference_gap_m.is_some_and(|g| g <= 0.0) {
                    self.phase = Phase::Approach {
                        since_s: t,
                        offset_m: 0.0,
                    };
                }
                match self.phase {
                    Phase::Approach { since_s, offset_m } => Decision::Position {
                        offset_m: offset_m + c.approach_speed_m_s * (t - since_s),
                        offset_rate_m_s: c.approach_speed_m_s,
                    },
                    _ => Decision::Position {
                        offset_m: 0.0,
                        offset_rate_m_s: 0.0,
                    },
                }
            }
            Phase::Force { since_s, from_n } => {
                self.below_s = if push_n < 0.5 * c.threshold_n {
                    self.below_s + dt
                } else {
                    0.0
                };
                if self.below_s >= c.loss_s - 1e-12 {
                    // Resume the approach from where the tool is, so the target does not jump.
                    let offset_m = match (reference_gap_m, tool_gap_m) {
                        (Some(r), Some(tool)) => (r - tool).max(0.0),
                        _ => 0.0,
                    };
                    self.phase = Phase::Approach {
                        since_s: t,
                        offset_m,
                    };
                    self.above_s = 0.0;
                    return Decision::Position {
                        offset_m,
                        offset_rate_m_s: c.approach_speed_m_s,
                    };
                }
                let ramp = if c.ramp_s > 0.0 {
                    ((t - since_s) / c.ramp_s).clamp(0.0, 1.0)
                } else {
                    1.0
                };
                Decision::Force {
                    just_switched: false,
                    ramp,
                    from_n,
                }
            }
        }
    }

    /// How many times force control has started.
    #[must_use]
    pub fn switches(&self) -> u32 {
        self.switches
    }
}
