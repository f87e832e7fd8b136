// ShpackResult.cs - what a conversion in memory returns (shpack_conversion of the C ABI), and
// the exception a failed one throws.
using System;
using UnityEngine.Rendering;

namespace Shpack
{
    public sealed class ShpackResult
    {
        public double[] RadianceSh;    // 27: L_c,i, channel-major
        public float[] UnitySh;        // 27: SphericalHarmonicsL2 sh[c, i] at 9c + i
        public float[] Shader;         // 28: unity_SHAr, SHAg, SHAb, SHBr, SHBg, SHBb, SHC
        public double[] MinEOverPi;    // 3: lowest E/pi over the sphere per channel
        public ulong NonFiniteTexels, NegativeTexels;
        public ShpackLight Sun;        // the extracted sun (ShpackOptions.ExtractSun), or null
        public ShpackLight[] Lights;   // the lights of ShpackOptions.ExtractLights, in the order chosen
        public uint LightCandidates;   // how many candidates they were chosen from
        public ShpackViewError ViewError;  // what Unity shows against the exact E/pi of the map
        public double[] WindowRmsChange;   // 3: the RMS change of E/pi the window made, over the RMS before it
        public int[] WindowPlanes;         // 3: "optimal": the directions its cutting planes needed

        public SphericalHarmonicsL2 ToSphericalHarmonicsL2()
        {
            return ShpackProbe.FromFloats(UnitySh);
        }
    }

    // diagnostics.unity_view_error_* of the document (docs/json-format.md): the error of
    // ShadeSH9 plus every extracted light against the exact E/pi of the input, in percent of
    // its mean E/pi, at Directions normals (RmsPct; MaxPct also searched for between them);
    // each within BoundPct of the exact error.
    public sealed class ShpackViewError
    {
        public double MaxPct, RmsPct, BoundPct;
        public uint Directions;
    }

    public sealed class ShpackException : Exception
    {
        public readonly int Code;  // the C ABI's return code (SHPACK_*)
        public ShpackException(int code, string message) : base(message) { Code = code; }
    }
}
