//! The RELATIVE position of the POS page: the operator's counters. As on
//! a Fanuc control they count the machine's motion (a change of work
//! system or of an offset that moves nothing leaves them as they are),
//! and the operator sets them per axis: ORIGIN zeroes one axis or all,
//! PRESET sets one to a value. The server keeps them, not the control.

/// The relative counters of every axis.
#[derive(Clone, Debug, PartialEq)]
pub struct Relative {
    /// Machine position of each axis when it was last set.
    base: Vec<f64>,
    /// The value it was set to then.
    preset: Vec<f64>,
}

impl Relative {
    /// Counters reading zero at `machine`.
    pub fn new(machine: &[f64]) -> Relative {
        Relative {
            base: machine.to_vec(),
            preset: vec![0.0; machine.len()],
        }
    }

    /// Sets axis `axis` (an index into the machine's axes; every axis when
    /// `None`) to `value` at the machine position `machine`.
    pub fn set(&mut self, axis: Option<usize>, value: f64, machine: &[f64]) {
        let counters = self.base.iter_mut().zip(self.preset.iter_mut());
        for (i, ((b, p), m)) in counters.zip(machine).enumerate() {
            if axis.is_none_or(|a| a == i) {
                *b = *m;
                *p = value;
            }
        }
    }

    /// The counters at the machine position `machine`.
    pub fn at(&self, machine: &[f64]) -> Vec<f64> {
        machine
            .iter()
            .zip(self.base.iter().zip(&self.preset))
            .map(|(m, (b, p))| p + (m - b))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counters_follow_motion_from_where_they_were_set() {
        // Zero at machine (-400, -200, 0); the tool moves 12.5 mm in X
        // and -3 mm in Z: the counters read 12.5, 0, -3.
        let r = Relative::new(&[-400.0, -200.0, 0.0]);
        assert_eq!(r.at(&[-387.5, -200.0, -3.0]), vec![12.5, 0.0, -3.0]);
    }

    #[test]
    fn origin_of_one_axis_leaves_the_others() {
        let mut r = Relative::new(&[0.0, 0.0, 0.0]);
        // At (10, 20, 30) only Y is zeroed; X and Z still count from 0.
        r.set(Some(1), 0.0, &[10.0, 20.0, 30.0]);
        assert_eq!(r.at(&[10.0, 20.0, 30.0]), vec![10.0, 0.0, 30.0]);
        // 5 mm further in +Y reads 5 on Y.
        assert_eq!(r.at(&[10.0, 25.0, 30.0]), vec![10.0, 5.0, 30.0]);
    }

    #[test]
    fn preset_sets_a_value_and_origin_all_zeroes_every_axis() {
        let mut r = Relative::new(&[0.0, 0.0]);
        // X preset to 100 at machine X 7: moving to X 2 reads 95.
        r.set(Some(0), 100.0, &[7.0, 1.0]);
        assert_eq!(r.at(&[2.0, 1.0]), vec![95.0, 1.0]);
        r.set(None, 0.0, &[2.0, 1.0]);
        assert_eq!(r.at(&[2.0, 1.0]), vec![0.0, 0.0]);
        assert_eq!(r.at(&[3.0, -1.0]), vec![1.0, -2.0]);
    }
}
