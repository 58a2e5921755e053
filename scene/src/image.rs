//! The final image every renderer of the kit produces.

/// The final image: linear RGB in [0, 1], row 0 at the top.
#[derive(Debug, Clone)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<[f64; 3]>,
}

impl Image {
    pub fn black(width: u32, height: u32) -> Image {
        Image {
            width,
            height,
            rgb: vec![[0.0; 3]; (width * height) as usize],
        }
    }

    /// 8-bit RGB bytes, rounded.
    pub fn to_rgb8(&self) -> Vec<u8> {
        self.rgb
            .iter()
            .flat_map(|p| p.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8))
            .collect()
    }
}
