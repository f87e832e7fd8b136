// ShpackMonoTest.cs - the Unity package (unity/) under Mono, without Unity: a map made in
// memory is converted through P/Invoke (ShpackNative over libshpack_c) and by the shpack
// command (from the same texels written as PFM), and the two must agree bit for bit; the
// editor script's JSON reading and probe assignment, and the command's C# output (the class
// ShpackStudio, compiled into this test), must give the document's floats exactly.
//
// Usage: mono ShpackMonoTest.exe <shpack command> <work folder> <studio.json>
// Exit code 0 when every check passes; each failure is printed.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Text;
using Shpack;
using Shpack.Editor;
using UnityEngine;
using UnityEngine.Rendering;

static class ShpackMonoTest
{
    static int failures;

    static void Check(bool ok, string what)
    {
        if (ok) return;
        ++failures;
        Console.Error.WriteLine("FAILED: " + what);
    }

    static int Bits(float f) { return BitConverter.ToInt32(BitConverter.GetBytes(f), 0); }

    static void CheckSameFloats(float[] got, float[] want, string what)
    {
        Check(got.Length == want.Length, what + ": length " + got.Length + " != " + want.Length);
        for (int k = 0; k < Math.Min(got.Length, want.Length); ++k)
            Check(Bits(got[k]) == Bits(want[k]), what + "[" + k + "]: " + got[k].ToString("R") + " != " + want[k].ToString("R"));
    }

    static void CheckProbe(SphericalHarmonicsL2 sh, float[] want, string what)
    {
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 9; ++i)
                Check(Bits(sh[c, i]) == Bits(want[9 * c + i]), what + " sh[" + c + ", " + i + "]");
    }

    // A 128 x 64 sky in memory: a vertical gradient, a warm sun disc of 3 degrees at
    // (lon 40, elevation 30 degrees), and a few small negative texels (as lossy EXR has).
    static float[] MakeSky(int width, int height)
    {
        var pixels = new float[width * height * 3];
        double sunLon = 40 * Math.PI / 180, sunElevation = 30 * Math.PI / 180;
        double sx = Math.Cos(sunElevation) * Math.Cos(sunLon), sy = Math.Sin(sunElevation), sz = Math.Cos(sunElevation) * Math.Sin(sunLon);
        for (int y = 0; y < height; ++y)
        {
            for (int x = 0; x < width; ++x)
            {
                // Unity's Skybox/Panoramic mapping (docs/conventions.md).
                double theta = Math.PI * (y + 0.5) / height, lon = (0.5 - (x + 0.5) / width) * 2 * Math.PI;
                double dx = Math.Sin(theta) * Math.Cos(lon), dy = Math.Cos(theta), dz = Math.Sin(theta) * Math.Sin(lon);
                bool sun = dx * sx + dy * sy + dz * sz > Math.Cos(1.5 * Math.PI / 180);
                int k = 3 * (y * width + x);
                pixels[k] = sun ? 5000f : (float)(0.3 + 0.5 * Math.Max(dy, 0));
                pixels[k + 1] = sun ? 4500f : (float)(0.4 + 0.6 * Math.Max(dy, 0));
                pixels[k + 2] = sun ? 4000f : (float)(0.6 + 0.9 * Math.Max(dy, 0));
            }
        }
        pixels[3 * (60 * width + 7) + 2] = -0.002f;
        return pixels;
    }

    // Portable Float Map: "PF", size, -1 (little-endian), then rows from the bottom up.
    static void WritePfm(string path, float[] pixels, int width, int height)
    {
        using (var file = new BinaryWriter(File.Create(path)))
        {
            file.Write(Encoding.ASCII.GetBytes("PF\n" + width + " " + height + "\n-1.0\n"));
            for (int y = height - 1; y >= 0; --y)
                for (int k = 0; k < width * 3; ++k) file.Write(pixels[3 * y * width + k]);  // BinaryWriter: little-endian
        }
    }

    static void RunCli(string cli, string arguments)
    {
        var info = new ProcessStartInfo(cli, arguments) { UseShellExecute = false, RedirectStandardError = true };
        using (Process process = Process.Start(info))
        {
            string err = process.StandardError.ReadToEnd();
            process.WaitForExit();
            if (process.ExitCode != 0) throw new Exception("shpack " + arguments + " failed: " + err);
        }
    }

    static int Main(string[] args)
    {
        string cli = args[0], work = args[1], studioJson = args[2];
        Directory.CreateDirectory(work);
        Check(ShpackNative.IsCompatible(), "the loaded shpack_c has the ABI version of ShpackNative");

        // 1. P/Invoke and the command on the same texels.
        const int width = 128, height = 64;
        float[] sky = MakeSky(width, height);
        string pfm = Path.Combine(work, "sky.pfm"), json = Path.Combine(work, "sky.json");
        WritePfm(pfm, sky, width, height);
        RunCli(cli, "convert \"" + pfm + "\" -o \"" + json + "\" --rotate 30 --intensity 0.5 --window sloan");
        var options = new ShpackOptions { RotateDeg = 30, Intensity = 0.5, Window = "sloan" };
        ShpackResult native = ShpackNative.ConvertEquirect(sky, width, height, 3, options);
        ShpackProbeData document = ShpackDocument.ReadFile(json)[0];
        CheckSameFloats(native.UnitySh, document.UnitySh, "sphericalHarmonicsL2");
        CheckSameFloats(native.Shader, document.Shader, "shader");
        for (int k = 0; k < 27; ++k)
            Check(BitConverter.DoubleToInt64Bits(native.RadianceSh[k]) == BitConverter.DoubleToInt64Bits(document.RadianceSh[k]),
                  "radiance_sh[" + k + "]: " + native.RadianceSh[k].ToString("R") + " != " + document.RadianceSh[k].ToString("R"));
        Check(native.NegativeTexels == 1, "one negative texel, got " + native.NegativeTexels);
        float[] rgb = ShpackNative.ShadeSH9(native.Shader, 0f, 1f, 0f);
        Check(rgb[0] > 0 && rgb[1] > 0 && rgb[2] > 0, "ShadeSH9 up is positive");

        // 2. Errors come back as exceptions with the library's message.
        sky[3 * (5 * width + 9)] = float.NaN;
        try
        {
            ShpackNative.ConvertEquirect(sky, width, height, 3, new ShpackOptions());
            Check(false, "a NaN texel is an error");
        }
        catch (ShpackException e)
        {
            Check(e.Code == 3 && e.Message.Contains("x=9, y=5"), "NaN texel reported as code 3 at x=9, y=5: " + e.Message);
        }

        // 3. The editor script: the ambient probe and the baked probes take the document's floats.
        Console.WriteLine(ShpackImporter.SetAmbientProbe(json));
        Check(RenderSettings.ambientMode == AmbientMode.Custom, "ambient mode Custom");
        CheckProbe(RenderSettings.ambientProbe, document.UnitySh, "ambientProbe");
        LightmapSettings.lightProbes = new LightProbes(new[] { new Vector3(0, 1, 0), new Vector3(5, 1, 0), new Vector3(0, 1, 5) });
        Console.WriteLine(ShpackImporter.SetBakedProbes(json));
        foreach (SphericalHarmonicsL2 probe in LightmapSettings.lightProbes.bakedProbes) CheckProbe(probe, document.UnitySh, "bakedProbes");

        // 4. The command's C# output, compiled into this test, builds the document's probe.
        ShpackProbeData studio = ShpackDocument.ReadFile(studioJson)[0];
        CheckProbe(ShpackStudio.Probe(), studio.UnitySh, "ShpackStudio.Probe()");

        // 5. A bad document is a FormatException naming the file and the value.
        string bad = Path.Combine(work, "bad.json");
        File.WriteAllText(bad, File.ReadAllText(json).Replace("\"unity_SHC\"", "\"unity_SHX\""));
        try
        {
            ShpackDocument.ReadFile(bad);
            Check(false, "a document without unity_SHC is an error");
        }
        catch (FormatException e)
        {
            Check(e.Message == bad + ": /shader: missing key \"unity_SHC\"", "message: " + e.Message);
        }

        Console.WriteLine(failures == 0 ? "ShpackMonoTest: all checks passed" : "ShpackMonoTest: " + failures + " failures");
        return failures == 0 ? 0 : 1;
    }
}
