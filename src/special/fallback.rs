//! The MP fallbacks of the f64 functions, counted in one place.
//!
//! Every f64 function first runs a native f64 method with a running error bound
//! and, where that bound misses the function's tolerance, falls back to the
//! certified MP path (module docs of [`crate::special`], "f64 policy"). A solver
//! that calls them in a loop wants to know how often that slow path ran: this
//! module holds one process-wide counter per f64 route, and [`fallback_counts`]
//! reads them all at once. Take a snapshot before and after a piece of work and
//! subtract ([`FallbackCounts::since`]).
//!
//! The counters are relaxed atomics: exact in a single thread, and exact in
//! total across threads once they have joined.

use std::sync::atomic::{AtomicU64, Ordering};

/// The f64 routes whose MP fallback is counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum F64Route {
    /// `bessel_j`, `bessel_j_bounded` (and the f64 sequences).
    BesselJ,
    /// `hyp1f2`, `hyp1f2_bounded` and the model family.
    Hyp1f2,
    /// `hyp2f1`, `hyp2f1_bounded`.
    Hyp2f1,
    /// `meijer_g_k`, `meijer_g_k_bounded` and the family.
    MeijerGK,
    /// `u_wave_bounded`, `du_wave_bounded`, `WaveBessel::eval_bounded` (per `x`).
    WaveBounded,
    /// The per-contact Bessel data of the bounded wave path built in MP (where
    /// the native double-double sequence does not certify, `D` beyond about 60).
    WaveBoundedMpContact,
}

const ROUTES: usize = 6;

static COUNTS: [AtomicU64; ROUTES] = [const { AtomicU64::new(0) }; ROUTES];

/// Records one MP fallback of `route`.
pub(crate) fn count(route: F64Route) {
    COUNTS[route as usize].fetch_add(1, Ordering::Relaxed);
}

fn load(route: F64Route) -> u64 {
    COUNTS[route as usize].load(Ordering::Relaxed)
}

/// How many times each f64 route fell back to MP since the process started.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct FallbackCounts {
    /// [`F64Route::BesselJ`].
    pub bessel_j: u64,
    /// [`F64Route::Hyp1f2`].
    pub hyp1f2: u64,
    /// [`F64Route::Hyp2f1`].
    pub hyp2f1: u64,
    /// [`F64Route::MeijerGK`].
    pub meijer_g_k: u64,
    /// [`F64Route::WaveBounded`].
    pub wave_bounded: u64,
    /// [`F64Route::WaveBoundedMpContact`].
    pub wave_bounded_mp_contacts: u64,
}

impl FallbackCounts {
    /// The count of one route.
    pub fn get(&self, route: F64Route) -> u64 {
        match route {
            F64Route::BesselJ => self.bessel_j,
            F64Route::Hyp1f2 => self.hyp1f2,
            F64Route::Hyp2f1 => self.hyp2f1,
            F64Route::MeijerGK => self.meijer_g_k,
            F64Route::WaveBounded => self.wave_bounded,
            F64Route::WaveBoundedMpContact => self.wave_bounded_mp_contacts,
        }
    }

    /// The fallbacks counted after `earlier` (a snapshot taken before), route by
    /// route (saturating, so a snapshot taken in the other order gives zeros).
    pub fn since(&self, earlier: &FallbackCounts) -> FallbackCounts {
        FallbackCounts {
            bessel_j: self.bessel_j.saturating_sub(earlier.bessel_j),
            hyp1f2: self.hyp1f2.saturating_sub(earlier.hyp1f2),
            hyp2f1: self.hyp2f1.saturating_sub(earlier.hyp2f1),
            meijer_g_k: self.meijer_g_k.saturating_sub(earlier.meijer_g_k),
            wave_bounded: self.wave_bounded.saturating_sub(earlier.wave_bounded),
            wave_bounded_mp_contacts: self.wave_bounded_mp_contacts.saturating_sub(earlier.wave_bounded_mp_contacts),
        }
    }

    /// All fallbacks, summed over the routes.
    pub fn total(&self) -> u64 {
        self.bessel_j + self.hyp1f2 + self.hyp2f1 + self.meijer_g_k + self.wave_bounded + self.wave_bounded_mp_contacts
    }
}

/// A snapshot of every route's fallback counter.
pub fn fallback_counts() -> FallbackCounts {
    FallbackCounts {
        bessel_j: load(F64Route::BesselJ),
        hyp1f2: load(F64Route::Hyp1f2),
        hyp2f1: load(F64Route::Hyp2f1),
        meijer_g_k: load(F64Route::MeijerGK),
        wave_bounded: load(F64Route::WaveBounded),
        wave_bounded_mp_contacts: load(F64Route::WaveBoundedMpContact),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snapshots_subtract_route_by_route() {
        let before = fallback_counts();
        count(F64Route::Hyp2f1);
        count(F64Route::Hyp2f1);
        count(F64Route::WaveBoundedMpContact);
        let d = fallback_counts().since(&before);
        // other tests of this process may count too, never less
        assert!(d.hyp2f1 >= 2 && d.wave_bounded_mp_contacts >= 1, "{d:?}");
        assert_eq!(d.get(F64Route::Hyp2f1), d.hyp2f1);
        assert!(d.total() >= 3);
        assert_eq!(before.since(&fallback_counts()).hyp2f1, 0);
    }
}
