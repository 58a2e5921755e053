//! Instance and port names as the emitted Verilog spells them, checked
//! against the rust-hdl structs: [`instance!`](crate::instance)`(Pipeline<1, 1, 1>, abc)`
//! is `"abc"`, and renaming or removing the field breaks the build.
//!
//! rust-hdl names a module by its instance path (`top$lanes$2$shader`) and
//! a signal by its field (`res_beat$0` for element 0 of the array
//! `res_beat`), so the names the kit matches in the emitted Verilog are the
//! field names of the structs. The field must be visible where the macro
//! is used (the units manifests sit beside the structs, in this crate).

/// The name of field `$f` of struct `$t` (a concrete type: const generics
/// given, e.g. `Pipeline<1, 1, 1>`), checked at compile time:
/// `instance!(T, f)` is `"f"`, `instance!(T, f[*])` is `"f$*"` (every
/// element of the array `f`) and `instance!(T, f[0])` is `"f$0"`.
#[macro_export]
macro_rules! instance {
    ($t:ty, $f:ident) => {{
        let _ = |w: &$t| {
            let _ = &w.$f;
        };
        stringify!($f)
    }};
    ($t:ty, $f:ident[*]) => {{
        let _ = |w: &$t| {
            let _ = &w.$f;
        };
        concat!(stringify!($f), "$*")
    }};
    ($t:ty, $f:ident[$i:literal]) => {{
        let _ = |w: &$t| {
            let _ = &w.$f[$i];
        };
        concat!(stringify!($f), "$", stringify!($i))
    }};
}
