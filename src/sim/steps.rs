//! How long a closed-loop run is, in plant steps, known before it starts.

use super::{SimConfig, SimError};

impl<const N: usize> SimConfig<N> {
    /// Number of RK4 plant steps [`super::simulate`] takes with these settings: whole
    /// control periods over `duration`, each of whole plant steps, rounded as the run rounds
    /// them. Saturates at `u64::MAX`; unlike the run, it does not refuse a large count, so
    /// that a caller can say how large.
    ///
    /// # Errors
    ///
    /// [`SimError::Config`] for a duration, plant step or control period the run would
    /// refuse.
    ///
    /// ```
    /// use armdyn::model::Scara;
    /// use armdyn::sim::SimConfig;
    ///
    /// let mut config = SimConfig::new(&Scara); // 10 s, 1 ms plant and controller
    /// assert_eq!(config.plant_steps(), Ok(10_000));
    /// config.plant_dt = 1e-9;
    /// assert_eq!(config.plant_steps(), Ok(10_000_000_000));
    /// ```
    pub fn plant_steps(&self) -> Result<u64, SimError> {
        // The run's own checks and rounding, without its cap on the number of samples.
        let (samples, substeps) = super::sample_counts(self)?;
        // `as` saturates beyond the range of u64.
        Ok((samples * substeps) as u64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::FreeSpace;
    use crate::control::open_loop::ZeroTorque;
    use crate::model::{JointVector, Scara, Wrench};
    use crate::sim::{simulate, ReferenceSource, Setpoint};
    use crate::target::CartesianTarget;
    use crate::target::JointTarget;
    use nalgebra::Vector3;

    struct Still;
    impl ReferenceSource<4> for Still {
        fn at(&mut self, _: f64) -> Setpoint<4> {
            let z = JointVector::<4>::zeros();
            Setpoint {
                joint: JointTarget {
                    q: z,
                    qd: z,
                    qdd: z,
                },
                cartesian: CartesianTarget::at_rest(
                    Vector3::zeros(),
                    crate::target::orientation::from_yaw(0.0),
                ),
                wrench: Wrench::zeros(),
            }
        }
    }

    #[test]
    fn counts_the_steps_the_run_takes() {
        for (duration, control_dt, plant_dt) in
            [(0.05, 1e-3, 1e-3), (0.0501, 2e-3, 5e-4), (0.0, 1e-3, 1e-4)]
        {
            let mut config = SimConfig::new(&Scara);
            config.duration = duration;
            config.control_dt = control_dt;
            config.plant_dt = plant_dt;
            let stats = simulate(
                &Scara,
                &mut ZeroTorque,
                &mut Still,
                &FreeSpace,
                &config,
                |_| {},
            )
            .unwrap();
            let substeps = (control_dt / plant_dt).round() as u64;
            // One sample at every control period, the last one without steps after it.
            assert_eq!(
                config.plant_steps().unwrap(),
                (stats.samples as u64 - 1) * substeps
            );
        }
    }

    #[test]
    fn large_counts_are_given_and_bad_settings_refused() {
        let mut config = SimConfig::new(&Scara);
        config.duration = 1e9;
        assert_eq!(config.plant_steps(), Ok(1_000_000_000_000));
        config.duration = 1e300;
        assert_eq!(config.plant_steps(), Ok(u64::MAX));
        config.plant_dt = 0.0;
        assert!(config.plant_steps().is_err());
        config.plant_dt = 3e-4;
        assert!(config.plant_steps().is_err()); // 1 ms is not a whole multiple of 0.3 ms
    }
}
