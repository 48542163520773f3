// Builds a scene graph in code, renders it offscreen and writes a PNG: how a C++ program
// embeds volsg. Usage: volsg-embed-example OUT.png
#include <cstdio>
#include <exception>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/Context.h>
#include <volsg/manipulators/ExaminerNavigation.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>
#include <volsg/render/Renderer.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    try {
        using namespace volsg;
        auto root = Separator::create();
        auto camera = PerspectiveCamera::create();
        camera->position = glm::vec3(0.0f, 0.0f, 6.0f);
        root->addChild(camera);
        auto light = DirectionalLight::create();
        light->direction = glm::vec3(-0.4f, -0.5f, -1.0f);
        root->addChild(light);

        // Three spheres share one Material and one Sphere node (instancing, as USE in files).
        auto material = Material::create();
        material->diffuseColor = {glm::vec3(0.9f, 0.5f, 0.2f)};
        auto sphere = Sphere::create();
        sphere->radius = 0.6f;
        for (int i = -1; i <= 1; ++i) {
            auto item = Separator::create();
            auto move = Transform::create();
            move->translation = glm::vec3(1.5f * float(i), 0.0f, 0.0f);
            item->addChild(move);
            item->addChild(material);
            item->addChild(sphere);
            root->addChild(item);
        }
        auto cone = Cone::create();
        auto under = Separator::create();
        auto down = Transform::create();
        down->translation = glm::vec3(0.0f, -1.5f, 0.0f);
        under->addChild(down);
        under->addChild(cone);
        root->addChild(under);

        // Frame the whole scene as the viewer's "view all" does.
        ExaminerNavigation navigation(camera, 480, 320);
        BoundingBoxAction bounds;
        bounds.apply(*root);
        navigation.viewAll(bounds.boundingBox());

        auto context = Context::createOffscreen(Backend::OSMesa);
        Renderer renderer;
        RenderOptions options;
        options.width = 480;
        options.height = 320;
        options.background = glm::vec3(0.1f, 0.1f, 0.15f);
        writePng(argv[1], renderer.render(*root, options));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "volsg-embed-example: %s\n", e.what());
        return 1;
    }
}
