//! The lane counts (`P`, a const generic of every block) the RTL is built
//! for, and the one dispatch from a run-time `p` to a build.

/// The `P` every block is built and tested for.
pub const BUILT: [usize; 4] = [1, 2, 4, 8];

/// The one check of a lane count against [`BUILT`], with the one message
/// every refusal gives.
pub fn built(p: usize) -> Result<(), String> {
    if BUILT.contains(&p) {
        Ok(())
    } else {
        Err(format!(
            "hardware.pipelines {p}: the RTL is built for 1, 2, 4 or 8 pipelines"
        ))
    }
}

/// Work for a `P` known only at run time: [`with_p`] calls `run::<P>`.
pub trait ForP {
    type Output;
    fn run<const P: usize>(self) -> Self::Output;
}

/// Run `f` for `p` lanes, or say which lane counts are built.
pub fn with_p<F: ForP>(p: usize, f: F) -> Result<F::Output, String> {
    match p {
        1 => Ok(f.run::<1>()),
        2 => Ok(f.run::<2>()),
        4 => Ok(f.run::<4>()),
        8 => Ok(f.run::<8>()),
        _ => built(p).map(|()| unreachable!("every built P is dispatched")),
    }
}
