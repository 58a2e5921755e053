//! Error metrics between a rendered image and the reference.

use scene::Image;
/// Error of an image against the reference (colours in [0, 1]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorMetrics {
    /// Cube-3 §6, "the average Euclidean distance of RGB values between
    /// corresponding pixels", as the kit reads it: over the foreground
    /// pixels (non-black in either image), relative to the largest possible
    /// distance sqrt(3), in percent. The figure every report leads with.
    pub rel_euclid_pct: f64,
    /// The same average over every pixel of the image, relative to sqrt(3)
    /// (another reading of §6: it shrinks as the background grows).
    pub rel_euclid_all_pct: f64,
    /// The foreground's summed Euclidean distance relative to the
    /// reference's summed RGB magnitude (`|rgb|` per pixel), in percent: a
    /// third reading, relative to what the reference shows rather than to
    /// full white. `None` when the reference is black where the image is
    /// not.
    pub rel_euclid_to_ref_pct: Option<f64>,
    /// Root mean square error over all pixels and channels.
    pub rmse: f64,
    /// `20 log10(1 / rmse)`; infinite for identical images.
    pub psnr_db: f64,
    /// Largest absolute channel difference.
    pub max_abs: f64,
    pub foreground_pixels: usize,
}

/// Compare `img` against `reference`: `None` when neither image has a
/// foreground pixel, where the relative error and the PSNR are undefined
/// (an empty scene, a transparent transfer function), never a 0. Panics if
/// the sizes differ (a caller bug).
pub fn compare(img: &Image, reference: &Image) -> Option<ErrorMetrics> {
    assert_eq!(
        (img.width, img.height),
        (reference.width, reference.height),
        "image sizes differ"
    );
    let fg_level = 0.5 / 255.0;
    let (mut euclid, mut fg, mut sq, mut max_abs) = (0.0, 0usize, 0.0, 0.0f64);
    let (mut euclid_all, mut ref_magnitude) = (0.0, 0.0);
    for (a, b) in img.rgb.iter().zip(&reference.rgb) {
        let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let e = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        sq += d.iter().map(|x| x * x).sum::<f64>();
        max_abs = d.iter().fold(max_abs, |m, x| m.max(x.abs()));
        euclid_all += e;
        if a.iter().chain(b.iter()).any(|&c| c > fg_level) {
            fg += 1;
            euclid += e;
            ref_magnitude += (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt();
        }
    }
    if fg == 0 {
        return None;
    }
    let rmse = (sq / (3 * img.rgb.len()) as f64).sqrt();
    Some(ErrorMetrics {
        rel_euclid_pct: 100.0 * euclid / (fg as f64 * 3f64.sqrt()),
        rel_euclid_all_pct: 100.0 * euclid_all / (img.rgb.len() as f64 * 3f64.sqrt()),
        rel_euclid_to_ref_pct: (ref_magnitude > 0.0).then(|| 100.0 * euclid / ref_magnitude),
        rmse,
        psnr_db: if rmse == 0.0 {
            f64::INFINITY
        } else {
            20.0 * (1.0 / rmse).log10()
        },
        max_abs,
        foreground_pixels: fg,
    })
}

/// Difference image: per-channel absolute difference times `gain`.
pub fn difference(img: &Image, reference: &Image, gain: f64) -> Image {
    let mut out = Image::black(img.width, img.height);
    for ((o, a), b) in out.rgb.iter_mut().zip(&img.rgb).zip(&reference.rgb) {
        *o = std::array::from_fn(|i| ((a[i] - b[i]).abs() * gain).min(1.0));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_images_have_zero_error() {
        let mut a = Image::black(4, 4);
        a.rgb[3] = [0.5, 0.2, 0.1];
        let m = compare(&a, &a).unwrap();
        assert_eq!(m.rel_euclid_pct, 0.0);
        assert_eq!(m.foreground_pixels, 1);
        assert!(m.psnr_db.is_infinite());
    }

    #[test]
    fn no_foreground_is_no_figure() {
        let a = Image::black(4, 4);
        assert_eq!(compare(&a, &a), None);
        let mut b = Image::black(4, 4);
        b.rgb[0] = [1.0 / 255.0, 0.0, 0.0];
        assert!(compare(&a, &b).is_some());
    }

    #[test]
    fn known_difference() {
        let mut a = Image::black(2, 1);
        let b = Image::black(2, 1);
        a.rgb[0] = [1.0, 1.0, 1.0];
        let m = compare(&a, &b).unwrap();
        assert!((m.rel_euclid_pct - 100.0).abs() < 1e-12);
        assert!((m.rmse - (0.5f64).sqrt()).abs() < 1e-12);
        assert_eq!(m.max_abs, 1.0);
        assert!((m.rel_euclid_all_pct - 50.0).abs() < 1e-12);
        assert_eq!(m.rel_euclid_to_ref_pct, None, "a black reference");
    }

    #[test]
    fn the_three_readings_by_hand() {
        // Four pixels: one background, a grey the image matches, and two
        // the image misses by (0.3, 0.4, 0) (distance 0.5) against
        // references (0.6, 0.8, 0) and (0, 0, 1) (magnitudes 1 and 1).
        let mut img = Image::black(4, 1);
        let mut reference = Image::black(4, 1);
        img.rgb[1] = [0.5, 0.5, 0.5];
        reference.rgb[1] = [0.5, 0.5, 0.5];
        img.rgb[2] = [0.3, 0.4, 0.0];
        reference.rgb[2] = [0.6, 0.8, 0.0];
        img.rgb[3] = [0.3, 0.4, 1.0];
        reference.rgb[3] = [0.0, 0.0, 1.0];
        let m = compare(&img, &reference).unwrap();
        assert_eq!(m.foreground_pixels, 3);
        let root3 = 3f64.sqrt();
        // Foreground: (0 + 0.5 + 0.5) / 3 / sqrt(3); all: 1.0 / 4 / sqrt(3).
        assert!((m.rel_euclid_pct - 100.0 / (3.0 * root3)).abs() < 1e-12);
        assert!((m.rel_euclid_all_pct - 100.0 / (4.0 * root3)).abs() < 1e-12);
        // Against the reference: 1.0 / (|grey| + 1 + 1), |grey| = sqrt(0.75).
        let want = 100.0 / (0.75f64.sqrt() + 2.0);
        assert!((m.rel_euclid_to_ref_pct.unwrap() - want).abs() < 1e-12);
    }
}
