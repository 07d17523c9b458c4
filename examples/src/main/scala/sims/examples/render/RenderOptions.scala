package sims.examples.render

/** What the [[Renderer]] draws besides bodies and joints: debugging overlays and a caption.
  *
  * @param contacts draw contact points and normals of the solver's last step (`world.contacts`;
  *                 the soft step's speculative points lighter)
  * @param boxes    draw every shape's axis-aligned bounding box
  * @param grid     draw the broadphase grid (cells of the detector's `gridSide`)
  * @param caption  text written in the upper-left corner (nothing when empty)
  * @param smooth   antialiased edges; off, the picture uses only [[Renderer.colours]], which
  *                 keeps GIF frames small
  */
final case class RenderOptions(contacts: Boolean = false, boxes: Boolean = false, grid: Boolean = false,
    caption: String = "", smooth: Boolean = true)
