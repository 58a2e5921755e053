//! Registers the host writes between frames (`golden_model::host`): `N`
//! 64-bit registers at fixed addresses of the host port, each taking the
//! port's data on a write to its address. Every block that needs a view
//! register keeps its own copy, written by the same broadcast write, so no
//! register fans out across the chip.

use rust_hdl::prelude::*;

/// The host port's address bits, defined with the host's register map.
pub use golden_model::host::ADDRESS_BITS;

/// `N` registers at the host addresses given to [`Regs::new`].
#[derive(LogicBlock)]
pub struct Regs<const N: usize> {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The registers' values.
    pub q: [Signal<Out, Bits<64>>; N],
    address: [Constant<Bits<ADDRESS_BITS>>; N],
    r: [DFF<Bits<64>>; N],
}

impl<const N: usize> Regs<N> {
    pub fn new(addresses: [u32; N]) -> Regs<N> {
        Regs {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            q: std::array::from_fn(|_| Default::default()),
            address: addresses.map(|a| Constant::new((a as u64).to_bits())),
            r: std::array::from_fn(|_| Default::default()),
        }
    }
}

impl<const N: usize> Logic for Regs<N> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..N {
            self.r[i].clock.next = self.clock.val();
            self.r[i].d.next = self.r[i].q.val();
            if self.host_write.val() & (self.host_address.val() == self.address[i].val()) {
                self.r[i].d.next = self.host_data.val();
            }
            self.q[i].next = self.r[i].q.val();
        }
    }
}
