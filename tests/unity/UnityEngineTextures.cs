// UnityEngineTextures.cs - the stub's textures (see UnityEngine.cs), holding the Color arrays
// that SetPixels gives them. Texture2D.GetPixels lays rows out bottom to top (Unity Scripting
// API); a Cubemap face's array is returned as it was set.
namespace UnityEngine
{
    public enum TextureFormat { RGBAHalf = 17, RGBAFloat = 20 }

    public enum CubemapFace { Unknown = -1, PositiveX = 0, NegativeX = 1, PositiveY = 2, NegativeY = 3, PositiveZ = 4, NegativeZ = 5 }

    public class Texture : Object
    {
        public int width { get; protected set; }
        public int height { get; protected set; }
    }

    public sealed class Texture2D : Texture
    {
        Color[] pixels;

        public Texture2D(int width, int height, TextureFormat format, bool mipChain)
        {
            this.width = width;
            this.height = height;
            pixels = new Color[width * height];
        }

        public void SetPixels(Color[] colors) { pixels = (Color[])colors.Clone(); }
        public Color[] GetPixels() { return (Color[])pixels.Clone(); }
    }

    public sealed class Cubemap : Texture
    {
        readonly Color[][] faces = new Color[6][];

        public Cubemap(int width, TextureFormat format, bool mipChain)
        {
            this.width = width;
            height = width;
        }

        public void SetPixels(Color[] colors, CubemapFace face) { faces[(int)face] = (Color[])colors.Clone(); }
        public Color[] GetPixels(CubemapFace face) { return (Color[])faces[(int)face].Clone(); }
    }
}
