//! `cube scenes`: list the built-in volumes, one per line with what each is.

use anyhow::Result;
use scene::volume::BUILTINS;

pub fn run() -> Result<()> {
    for (name, what) in BUILTINS {
        println!("{name:<13} {what}");
    }
    Ok(())
}
