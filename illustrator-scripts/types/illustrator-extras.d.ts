// Members of Illustrator's scripting DOM that the Scripting Reference documents but the published
// typings (types-for-adobe/Illustrator/2022) omit. Each cites its source; nothing is invented.

interface Document {
  /**
   * Retrieves the page item with this uuid (PageItem.uuid). Added in Illustrator 24.0 (CC 2020):
   * ai-scripting.docsforadobe.dev, Document.getPageItemFromUuid. Throws when no item has the uuid.
   * Optional here because Illustrator 22–23 lack it; the bridge checks before calling.
   */
  getPageItemFromUuid?: (uuid: string) => PageItem
}

interface TextFrameItems {
  /**
   * Creates a point text frame whose baseline starts at `anchor`. An instance method of the
   * collection (ai-scripting.docsforadobe.dev, TextFrameItems.pointText:
   * `app.activeDocument.textFrames.pointText(anchor[, orientation])`); the 2022 typings declare it
   * static by mistake.
   */
  pointText(anchor: Point | [number, number], orientation?: TextOrientation): TextFrame
}
