//! What tripped the supervisor: the cause, the time and the value against its limit.

/// Why the supervisor tripped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TripCause {
    /// A reading with a NaN or infinite axis.
    SensorNonFinite,
    /// A reading beyond the sensor's range.
    SensorRange,
    /// Fresh readings repeating bitwise for longer than the frozen time.
    SensorFrozen,
    /// No new reading for longer than the stale time.
    SensorStale,
    /// The measured force above its limit.
    Force,
    /// The measured force rising faster than its limit.
    ForceRate,
    /// An oscillating contact force.
    Oscillation,
    /// The contact lost under force control.
    ContactLost,
    /// The tool faster than its limit.
    ToolSpeed,
    /// The tool outside the workspace box.
    Workspace,
    /// A joint closer to a limit than its margin (the joint's index).
    JointLimit(u8),
    /// A joint faster than its limit.
    JointSpeed(u8),
    /// The controller's torque NaN or infinite (the joint's index).
    TorqueNonFinite(u8),
}

impl TripCause {
    /// Its name in reports (`sensor-nan`, `force`, `joint-limit`, ...).
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::SensorNonFinite => "sensor-non-finite",
            Self::SensorRange => "sensor-range",
            Self::SensorFrozen => "sensor-frozen",
            Self::SensorStale => "sensor-stale",
            Self::Force => "force",
            Self::ForceRate => "force-rate",
            Self::Oscillation => "oscillation",
            Self::ContactLost => "contact-lost",
            Self::ToolSpeed => "tool-speed",
            Self::Workspace => "workspace",
            Self::JointLimit(_) => "joint-limit",
            Self::JointSpeed(_) => "joint-speed",
            Self::TorqueNonFinite(_) => "torque-non-finite",
        }
    }

    /// The joint it is about, if any.
    #[must_use]
    pub fn joint(&self) -> Option<usize> {
        match self {
            Self::JointLimit(i) | Self::JointSpeed(i) | Self::TorqueNonFinite(i) => {
                Some(usize::from(*i))
            }
            _ => None,
        }
    }

    /// The unit of its value and limit.
    #[must_use]
    pub fn unit(&self) -> &'static str {
        match self {
            Self::SensorNonFinite | Self::SensorRange | Self::Force | Self::Oscillation => "N",
            Self::SensorFrozen | Self::SensorStale | Self::ContactLost => "s",
            Self::ForceRate => "N/s",
            Self::ToolSpeed => "m/s",
            Self::Workspace => "m",
            Self::JointLimit(_) => "rad or m",
            Self::JointSpeed(_) => "rad/s or m/s",
            Self::TorqueNonFinite(_) => "N m or N",
        }
    }
}

/// One trip: what, when, and the value that crossed the limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trip<T> {
    /// The cause.
    pub cause: TripCause,
    /// When, s.
    pub t: T,
    /// The value that tripped it (in [`TripCause::unit`]; for a joint limit the distance
    /// left to the limit, for the workspace the distance outside the box, for the
    /// sensor's frozen, stale and the contact-lost checks how long it lasted).
    pub value: T,
    /// The limit it crossed.
    pub limit: T,
}

/// Most trips kept per run: the first one latches the reaction; later ones are other causes
/// crossing their limits while it is latched (each cause once).
pub const MAX_TRIPS: usize = 8;

/// The trips of a run, in order (no allocation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TripLog<T> {
    trips: [Option<Trip<T>>; MAX_TRIPS],
    len: usize,
}

impl<T: Copy> Default for TripLog<T> {
    fn default() -> Self {
        Self {
            trips: [None; MAX_TRIPS],
            len: 0,
        }
    }
}

impl<T: Copy> TripLog<T> {
    /// Records `trip` unless its cause is already recorded or the log is full; `true` if it
    /// is the first trip.
    #[cold]
    #[inline(never)]
    pub fn record(&mut self, trip: Trip<T>) -> bool {
        if self.len == MAX_TRIPS || self.iter().any(|t| t.cause == trip.cause) {
            return false;
        }
        self.trips[self.len] = Some(trip);
        self.len += 1;
        self.len == 1
    }

    /// The first trip, the one that latched the reaction.
    #[must_use]
    pub fn first(&self) -> Option<&Trip<T>> {
        self.trips[0].as_ref()
    }

    /// Every trip, in order.
    pub fn iter(&self) -> impl Iterator<Item = &Trip<T>> {
        self.trips[..self.len].iter().flatten()
    }

    /// How many.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// None yet.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}
