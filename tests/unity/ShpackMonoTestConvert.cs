// ShpackMonoTestConvert.cs - ShpackNative's conversions against the shpack command on the
// same texels, bit for bit: an equirect map from floats and from a Texture2D (rows bottom
// up), a horizontal cross, a Cubemap's six faces, a sampling method and the extracted sun;
// errors as ShpackException; a document the reader refuses.
using System;
using System.IO;
using Shpack;
using UnityEngine;

static partial class ShpackMonoTest
{
    const int SkyWidth = 128, SkyHeight = 64;

    static void CheckConversions()
    {
        CheckEquirect();
        CheckCross();
        CheckCubemap();
        CheckMethodAndSun();
        CheckErrors();
    }

    static void CheckEquirect()
    {
        float[] sky = MakeSky(SkyWidth, SkyHeight);
        string pfm = WritePfm("sky.pfm", sky, SkyWidth, SkyHeight);
        string json = RunCli("\"" + pfm + "\" --rotate 30 --intensity 0.5 --exposure 1 --window sloan", "sky.json");
        var options = new ShpackOptions { RotateDeg = 30, Intensity = 0.5, ExposureEv = 1, Window = "sloan" };
        ShpackResult native = ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, options);
        CheckResultIsDocument(native, ShpackDocument.ReadFile(json)[0], "equirect");
        Check(native.NegativeTexels == 1, "one negative texel, got " + native.NegativeTexels);
        Check(native.Sun == null, "no sun without ExtractSun");
        float[] rgb = ShpackNative.ShadeSH9(native.Shader, 0f, 1f, 0f);
        Check(rgb[0] > 0 && rgb[1] > 0 && rgb[2] > 0, "ShadeSH9 up is positive");

        // The same map as a Texture2D, whose GetPixels rows run bottom to top, with its layout
        // detected from its 2:1 size: the same texels, so the same bits.
        var texture = new Texture2D(SkyWidth, SkyHeight, TextureFormat.RGBAFloat, false);
        texture.SetPixels(BottomUpColors(sky, SkyWidth, SkyHeight));
        ShpackResult fromTexture = ShpackNative.ConvertTexture(texture, ShpackLayout.Auto, options);
        CheckSameFloats(fromTexture.UnitySh, native.UnitySh, "ConvertTexture(equirect)");
        CheckSameDoubles(fromTexture.RadianceSh, native.RadianceSh, "ConvertTexture(equirect) radiance");
    }

    static void CheckCross()
    {
        const int n = 16;
        float[] cross = Noise(4 * n, 3 * n, 11);
        string pfm = WritePfm("cross.pfm", cross, 4 * n, 3 * n);
        string json = RunCli("\"" + pfm + "\" --layout hcross --cube-frame gl --negative clamp --l1", "cross.json");
        var texture = new Texture2D(4 * n, 3 * n, TextureFormat.RGBAFloat, false);
        texture.SetPixels(BottomUpColors(cross, 4 * n, 3 * n));
        var options = new ShpackOptions { CubeFrame = ShpackCubeFrame.Gl, ClampNegative = true, L1 = true };
        CheckResultIsDocument(ShpackNative.ConvertTexture(texture, ShpackLayout.HorizontalCross, options),
                              ShpackDocument.ReadFile(json)[0], "hcross");
    }

    static readonly string[] FaceNames = { "px", "nx", "py", "ny", "pz", "nz" };  // CubemapFace order

    // A Cubemap's face arrays are read with row 0 at the top of the face (docs/conventions.md),
    // as the command reads a face file.
    static Cubemap MakeCubemap(int n)
    {
        var cubemap = new Cubemap(n, TextureFormat.RGBAFloat, false) { name = "cubemap" };
        for (int f = 0; f < 6; ++f)
        {
            float[] face = Noise(n, n, (uint)(30 + f));
            WritePfm("face_" + FaceNames[f] + ".pfm", face, n, n);
            var colors = new Color[n * n];
            for (int k = 0; k < n * n; ++k) colors[k] = new Color(face[3 * k], face[3 * k + 1], face[3 * k + 2], 1f);
            cubemap.SetPixels(colors, (CubemapFace)f);
        }
        return cubemap;
    }

    static void CheckCubemap()
    {
        Cubemap cubemap = MakeCubemap(16);
        string json = RunCli("--faces \"" + Path.Combine(work, "face_{face}.pfm") + "\" --rotate 10 --window hanning:4", "faces.json");
        var options = new ShpackOptions { RotateDeg = 10, Window = "hanning:4" };
        CheckResultIsDocument(ShpackNative.ConvertCubemap(cubemap, options), ShpackDocument.ReadFile(json)[0], "ConvertCubemap");
    }

    static void CheckMethodAndSun()
    {
        float[] sky = MakeSky(SkyWidth, SkyHeight);
        string pfm = Path.Combine(work, "sky.pfm");
        string json = RunCli("\"" + pfm + "\" --method qmc:2048:5", "qmc.json");
        CheckResultIsDocument(ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, new ShpackOptions { Method = "qmc:2048:5" }),
                              ShpackDocument.ReadFile(json)[0], "qmc:2048:5");

        json = RunCli("\"" + pfm + "\" --extract-sun --rotate 15", "sun.json");
        ShpackResult native = ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, new ShpackOptions { ExtractSun = true, RotateDeg = 15 });
        ShpackDocumentData document = ShpackDocument.LoadFile(json);
        CheckResultIsDocument(native, document.Probes[0], "extract-sun");
        Check(native.Sun != null && document.Lights.Count == 1, "the sun is found by both");
        if (native.Sun != null && document.Lights.Count == 1) CheckSameLight(native.Sun, document.Lights[0], "sun");

        // --extract-lights: the same lights, in the same order, and the view error of the
        // result, searched for from the directions the last light chosen was measured at
        // (view_error.h), so at least its error, up to the float rounding of the fill levels
        // (light_candidates.h: 2^-24 of a texel's value, far below 1e-4 %).
        json = RunCli("\"" + pfm + "\" --extract-lights 3", "lights.json");
        native = ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, new ShpackOptions { ExtractLights = 3 });
        document = ShpackDocument.LoadFile(json);
        CheckResultIsDocument(native, document.Probes[0], "extract-lights");
        Check(native.Lights.Length >= 1 && native.Lights.Length == document.Lights.Count,
              "the lights are found by both: " + native.Lights.Length + " and " + document.Lights.Count);
        for (int k = 0; k < Math.Min(native.Lights.Length, document.Lights.Count); ++k)
        {
            CheckSameLight(native.Lights[k], document.Lights[k], "light " + k);
            Check(native.Lights[k].ErrorAfterPct < native.Lights[k].ErrorBeforePct, "light " + k + " lowers the error");
        }
        ShpackViewError error = native.ViewError;
        Check(error.Directions == 512 && error.BoundPct >= 0 && error.RmsPct <= error.MaxPct, "the view error is filled in");
        if (native.Lights.Length >= 1)
            Check(error.MaxPct > native.Lights[native.Lights.Length - 1].ErrorAfterPct - 1e-4,
                  "the view error is at least the last light's error after it: " + error.MaxPct);
    }

    static void CheckSameLight(ShpackLight got, ShpackLight want, string what)
    {
        CheckSameDoubles(got.Direction, want.Direction, what + ".direction");
        CheckSameDoubles(got.Irradiance, want.Irradiance, what + ".irradiance");
        CheckSameDoubles(got.Quaternion, want.Quaternion, what + ".quaternion");
        CheckSameDoubles(got.Color, want.Color, what + ".color");
        CheckSameDoubles(got.ColorSrgb, want.ColorSrgb, what + ".color_srgb");
        CheckSameDoubles(new[] { got.Intensity }, new[] { want.Intensity }, what + ".intensity");
    }

    static void CheckErrors()
    {
        float[] sky = MakeSky(SkyWidth, SkyHeight);
        sky[3 * (5 * SkyWidth + 9)] = float.NaN;
        try
        {
            ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, new ShpackOptions());
            Check(false, "a NaN texel is an error");
        }
        catch (ShpackException e)
        {
            Check(e.Code == 3 && e.Message.Contains("x=9, y=5"), "NaN texel reported as code 3 at x=9, y=5: " + e.Message);
        }
        try
        {
            ShpackNative.ConvertCubemap(MakeCubemap(4), new ShpackOptions { ExtractSun = true });
            Check(false, "ExtractSun on a cubemap is an error");
        }
        catch (ShpackException e)
        {
            Check(e.Code == 1, "ExtractSun on a cubemap: invalid argument, got " + e.Code + ": " + e.Message);
        }

        // A bad document is a FormatException naming the file and the value.
        string json = Path.Combine(work, "sky.json"), bad = Path.Combine(work, "bad.json");
        File.WriteAllText(bad, File.ReadAllText(json).Replace("\"unity_SHC\"", "\"unity_SHX\""));
        CheckRefused(bad, bad + ": /shader: missing key \"unity_SHC\"");
        File.WriteAllText(bad, File.ReadAllText(json) + "]");
        CheckRefused(bad, bad + ": not valid JSON");
    }

    static void CheckRefused(string path, string messageStart)
    {
        try
        {
            ShpackDocument.ReadFile(path);
            Check(false, path + " is refused");
        }
        catch (FormatException e)
        {
            Check(e.Message.StartsWith(messageStart, StringComparison.Ordinal), "message: " + e.Message);
        }
    }
}
