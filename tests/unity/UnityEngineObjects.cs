// UnityEngineObjects.cs - the stub's objects (see UnityEngine.cs): Object, GameObject and the
// components the package makes. GameObjects live in one list, the open scene, so that
// FindObjectsOfType and DestroyImmediate behave as in a scene.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public class Object
    {
        public string name = "";

        internal virtual Object Copy() { return (Object)MemberwiseClone(); }

        public static T Instantiate<T>(T original) where T : Object { return (T)original.Copy(); }

        public static T[] FindObjectsOfType<T>() where T : Object
        {
            var found = new List<T>();
            foreach (GameObject gameObject in GameObject.Scene)
                foreach (Component component in gameObject.components)
                    if (component is T) found.Add((T)(Object)component);
            return found.ToArray();
        }

        public static void DestroyImmediate(Object obj)
        {
            var gameObject = obj as GameObject;
            if (gameObject != null) GameObject.Scene.Remove(gameObject);
            var component = obj as Component;
            if (component != null) component.gameObject.components.Remove(component);
        }
    }

    public sealed class GameObject : Object
    {
        public static readonly List<GameObject> Scene = new List<GameObject>();
        internal readonly List<Component> components = new List<Component>();
        public readonly Transform transform;

        public GameObject(string name)
        {
            this.name = name;
            transform = AddComponent<Transform>();
            Scene.Add(this);
        }

        public T AddComponent<T>() where T : Component
        {
            var component = (T)Activator.CreateInstance(typeof(T), true);
            component.gameObject = this;
            components.Add(component);
            return component;
        }

        public T GetComponent<T>() where T : Component
        {
            foreach (Component component in components)
                if (component is T) return (T)component;
            return null;
        }
    }

    public class Component : Object
    {
        public GameObject gameObject { get; internal set; }
        public Transform transform { get { return gameObject.transform; } }
        public T GetComponent<T>() where T : Component { return gameObject.GetComponent<T>(); }
    }

    public class Behaviour : Component { }

    public class MonoBehaviour : Behaviour { }

    public sealed class Transform : Component
    {
        public Quaternion rotation;
    }

    public enum LightType { Spot = 0, Directional = 1, Point = 2 }

    public enum LightShadows { None = 0, Hard = 1, Soft = 2 }

    public sealed class Light : Behaviour
    {
        public LightType type = LightType.Point;
        public Color color = new Color(1, 1, 1);
        public float intensity = 1;
        public LightShadows shadows;
    }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class ExecuteAlways : Attribute { }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DisallowMultipleComponent : Attribute { }
}
