// ShpackLight.cs - a light taken out of a map (`convert --extract-sun`): the document's "sun"
// (docs/json-format.md) or shpack_light of the C ABI, in Unity's frame, and the directional
// light that adds it back (lib/include/shpack/unity_light.h says how each value is derived).
using UnityEngine;

namespace Shpack
{
    public sealed class ShpackLight
    {
        public double[] Direction;   // 3: unit, towards the light
        public double[] Irradiance;  // 3: E per channel at normal incidence
        public double[] Quaternion;  // 4: x, y, z, w; turns +Z (a light's forward) towards -Direction
        public double[] Color;       // 3: linear, largest channel 1
        public double[] ColorSrgb;   // 3: the same colour sRGB-encoded, as Light.color holds it
        public double Intensity;     // Color * Intensity = Irradiance / pi
        // `--extract-lights`: the max error of what Unity shows (ShpackViewError) with the
        // lights chosen before this one, and with it too; NaN for a sun.
        public double ErrorBeforePct = double.NaN, ErrorAfterPct = double.NaN;

        public Quaternion Rotation()
        {
            return new Quaternion((float)Quaternion[0], (float)Quaternion[1], (float)Quaternion[2], (float)Quaternion[3]);
        }

        // Light.color: Unity multiplies the linearised colour by the intensity in a linear
        // colour-space project (GraphicsSettings.lightsUseLinearIntensity), so the field takes
        // the sRGB-encoded colour.
        public Color LightColor()
        {
            return new Color((float)ColorSrgb[0], (float)ColorSrgb[1], (float)ColorSrgb[2], 1f);
        }

        // The same light: the same direction and irradiance, as doubles.
        public bool SameAs(ShpackLight other)
        {
            for (int k = 0; k < 3; ++k)
                if (Direction[k] != other.Direction[k] || Irradiance[k] != other.Irradiance[k]) return false;
            return true;
        }
    }
}
