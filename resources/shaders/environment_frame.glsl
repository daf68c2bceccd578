// The environment's rotation and intensity, applied at shading time (every IBL texture is in
// the image's frame at intensity 1: render/IblTextures.h). One declaration for every chunk that
// looks the environment up.
uniform mat3 uEnvironmentRotation; // world -> image frame: Environment::toImageFrame; its transpose is toWorldFrame
uniform float uEnvironmentIntensity;
