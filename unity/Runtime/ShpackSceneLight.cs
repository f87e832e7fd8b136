// ShpackSceneLight.cs - marks a Directional Light that shpack made for light `Index` of a
// document (its "sun", then its "lights"), so that applying a document again updates that
// light, or removes it when the document has fewer, instead of adding a second one: the SH
// of such a document has the light taken out, and each light must be counted exactly once.
using UnityEngine;

namespace Shpack
{
    [DisallowMultipleComponent]
    public sealed class ShpackSceneLight : MonoBehaviour
    {
        public int Index;
    }
}
