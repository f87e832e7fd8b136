// ShpackProbe.cs - the 27 floats of a shpack document as a SphericalHarmonicsL2.
using System;
using UnityEngine.Rendering;

namespace Shpack
{
    public static class ShpackProbe
    {
        // sh[c, i] = floats[9c + i]: the layout of the document's sphericalHarmonicsL2 and of
        // Unity's serialised sh[ 0]..sh[26] (docs/json-format.md). Unity's indexer takes
        // (channel, coefficient) and stores the floats as given.
        public static SphericalHarmonicsL2 FromFloats(float[] floats)
        {
            if (floats == null || floats.Length != 27) throw new ArgumentException("a SphericalHarmonicsL2 has 27 floats");
            var sh = new SphericalHarmonicsL2();
            for (int c = 0; c < 3; ++c)
                for (int i = 0; i < 9; ++i)
                    sh[c, i] = floats[9 * c + i];
            return sh;
        }
    }
}
