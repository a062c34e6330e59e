//! SplitMix64: the small, seeded generator behind the supersampler's random sample positions (the
//! same seed gives the same positions on every machine) and the seeded test scenes.

/// SplitMix64: a small, fast, well-mixed generator; enough for reproducible test data.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [low, high).
    pub fn uniform(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.unit()
    }

    /// Log-uniform in [low, high) (both > 0): every decade equally likely.
    pub fn log_uniform(&mut self, low: f64, high: f64) -> f64 {
        (low.ln() + (high.ln() - low.ln()) * self.unit()).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_uniform_covers_the_decades() {
        let mut rng = SplitMix64::new(1);
        let values: Vec<f64> = (0..10_000).map(|_| rng.log_uniform(1e-8, 1e8)).collect();
        assert!(values.iter().all(|&v| (1e-8..1e8).contains(&v)));
        let below_one = values.iter().filter(|&&v| v < 1.0).count();
        assert!((4_000..6_000).contains(&below_one), "{below_one}");
    }
}
