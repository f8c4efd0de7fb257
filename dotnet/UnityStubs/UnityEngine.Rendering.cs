// Stand-ins for the rendering types the package's prefab builder uses, after UnityCsReference: Runtime/Export/Graphics/
// Mesh.bindings.cs (Mesh : Object), Runtime/Export/Shaders/Material.bindings.cs (Material : Object),
// Runtime/Export/Graphics/GraphicsComponents.bindings.cs (MeshFilter : Component with sharedMesh; Renderer : Component with
// sharedMaterial and sharedMaterials; MeshRenderer : Renderer). Bodies are plain storage.
namespace UnityEngine
{
    public sealed class Mesh : Object
    {
        public Mesh() { }
    }

    public class Material : Object
    {
        // Material(Shader shader): a new material using the shader (Material.bindings.cs).
        public Material(Shader shader) => this.shader = shader;

        public Shader shader { get; set; }
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get; set; }
    }

    public class Renderer : Component
    {
        Material[] materials = new Material[0];

        // sharedMaterial: the first material; setting it makes it the only one (Renderer.bindings.cs GetSharedMaterial/SetMaterial).
        public Material sharedMaterial
        {
            get => materials.Length > 0 ? materials[0] : null;
            set => materials = new[] { value };
        }

        // sharedMaterials hands out a copy.
        public Material[] sharedMaterials
        {
            get => (Material[])materials.Clone();
            set => materials = (Material[])(value ?? new Material[0]).Clone();
        }
    }

    public sealed class MeshRenderer : Renderer { }
}

namespace UnityEngine
{
    // Runtime/Export/Shaders/Shader.bindings.cs: Shader.Find(string name) (null when no shader of that name is loaded;
    // here any name is found).
    public sealed class Shader : Object
    {
        public static Shader Find(string name) => string.IsNullOrEmpty(name) ? null : new Shader { name = name };
    }
}
