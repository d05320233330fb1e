<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/files.xsl - models split over several files: find the files a
  model references, load each once, and merge them into one normalised
  document that the rest of the import reads as if it were one file.

  Reads:   the XMI document (the model file) and, through doc(), the model
           files its hrefs name ("../components/Arm.compdef.uml#_id"), and
           theirs, each once (cycles are fine).
  Writes:  fp:linked-files: the URIs of those files; fp:merged: the
           normalised model file with every linked file's model root as a
           nested package (x:type Model, x:file its path relative to the
           model file) and every linked file's stereotype applications
           beside the model's own, hrefs into loaded files turned into
           x:idref (so references across files resolve through the keys
           like references inside one).
  Params:  $roots of fp:linked-files: the folder URIs a file may be read
           from (the model's folder and the model path: import.xsl's
           model-path).
  Which hrefs name a file to load: a relative or file: URI with a document
  part, outside a profile application, that is not a library the import
  knows (fp:href-library, pathmap:// and the like) and not a profile
  (*.profile.uml / *.profile.xmi: stereotypes are read from their
  applications). Never the network: any other scheme stays an external
  reference, as before.
  Errors:  IMP040 a file outside the model's folder and the model path
           (the sandbox); ID is the referencing element's xmi:id.
  Warnings: IMP041 a referenced file that is not there (its elements are
           left out; the references stay external, as for a library).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <!-- ================================================ which files -->
  <!-- the document part of an href that names a model file to load, else () -->
  <xsl:function name="fp:model-file-ref" as="xs:string?">
    <xsl:param name="href" as="attribute()"/>
    <xsl:variable name="doc" as="xs:string?" select="fp:model-file-doc(fp:href-doc($href))"/>
    <xsl:sequence select="
        if (empty($doc)) then ()
        else if ($href/ancestor::*[local-name() = ('profileApplication', 'appliedProfile')]) then ()
        else $doc"/>
  </xsl:function>

  <!-- the document part of an href ('' when it has none) -->
  <xsl:function name="fp:href-doc" as="xs:string">
    <xsl:param name="href" as="xs:string"/>
    <xsl:sequence select="substring-before($href || '#', '#')"/>
  </xsl:function>

  <!-- $doc (the document part of an href) when, by the text alone, it may
       name a model file to load (fp:model-file-ref without the place of
       the href), else () -->
  <xsl:function name="fp:model-file-doc" as="xs:string?">
    <xsl:param name="doc" as="xs:string"/>
    <xsl:sequence select="
        if ($doc eq '' or matches($doc, '\.profile\.(uml|xmi)$', 'i')) then ()
        else if (matches($doc, '^[A-Za-z][A-Za-z0-9+.\-]*:') and not(starts-with(lower-case($doc), 'file:'))) then ()
        else if (fp:href-library($doc) ne 'external') then ()
        else $doc"/>
  </xsl:function>

  <!-- a file URI in one spelling (file:/a, file:///a: engines differ) -->
  <xsl:function name="fp:uri-key" as="xs:string">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="replace($uri, '^file:/+', 'file:/')"/>
  </xsl:function>

  <!-- whether file URI $uri is inside one of the sandbox folders $roots
       (the model's folder and the model path): IMP040 otherwise -->
  <xsl:function name="fp:in-sandbox" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:param name="roots" as="xs:string*"/>
    <xsl:sequence select="some $root in $roots satisfies starts-with(fp:uri-key($uri), fp:uri-key($root))"/>
  </xsl:function>

  <!-- the element whose reference $href is, for messages: the nearest
       element with an xmi:id -->
  <xsl:function name="fp:referrer" as="element()?">
    <xsl:param name="href" as="attribute()"/>
    <xsl:sequence select="$href/ancestor::*[@*[local-name() eq 'id'][fp:is-xmi-ns(namespace-uri())]][1]"/>
  </xsl:function>

  <!-- the absolute URIs of the model files $doc references directly, each
       checked against the sandbox $roots (IMP040) and for existence
       (IMP041) -->
  <xsl:function name="fp:file-refs" as="xs:string*">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="roots" as="xs:string*"/>
    <!-- the few distinct document parts are tested first: the many hrefs
         into libraries (pathmap://...) are then passed over without a
         call each -->
    <xsl:variable name="hrefs" as="attribute()*" select="$doc//@href"/>
    <xsl:variable name="files" as="xs:string*"
        select="distinct-values($hrefs ! fp:href-doc(.))[exists(fp:model-file-doc(.))]"/>
    <xsl:for-each-group select="if (empty($files)) then () else $hrefs[fp:href-doc(.) = $files][fp:model-file-ref(.)]"
                        group-by="string(resolve-uri(fp:model-file-ref(.), base-uri(..)))">
      <xsl:variable name="uri" as="xs:string" select="current-grouping-key()"/>
      <xsl:variable name="who" as="element()?" select="fp:referrer(.)"/>
      <xsl:variable name="id" as="xs:string" select="string($who/@*[local-name() eq 'id'][fp:is-xmi-ns(namespace-uri())])"/>
      <xsl:variable name="what" as="xs:string"
          select="(if ($who) then local-name($who) || ' ' || (($who/@name, '')[1]) else 'an element') || ' refers to ''' || . || ''''"/>
      <xsl:choose>
        <xsl:when test="not(fp:in-sandbox($uri, $roots))">
          <xsl:sequence select="f:fail('IMP040', $id, $what || ', a file outside the model''s folder and the model path ('
              || $uri || '): robomda reads only files there; add its folder with --model-path DIR')"/>
        </xsl:when>
        <xsl:when test="not(doc-available($uri))">
          <xsl:sequence select="f:warn('IMP041', $id, $what || ', but ' || $uri || ' is not there (or not XML): '
              || 'the elements of that file are left out and its references stay unresolved; '
              || 'put it there or add its folder with --model-path DIR')"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:sequence select="$uri"/>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each-group>
  </xsl:function>

  <!-- every model file reachable from $main through fp:file-refs, each
       once, in the order first reached (breadth first) -->
  <xsl:function name="fp:linked-files" as="xs:string*">
    <xsl:param name="main" as="document-node()"/>
    <xsl:param name="roots" as="xs:string*"/>
    <xsl:sequence select="fp:gather(fp:file-refs($main, $roots), string(base-uri($main)), $roots)"/>
  </xsl:function>

  <xsl:function name="fp:gather" as="xs:string*">
    <xsl:param name="todo" as="xs:string*"/>
    <xsl:param name="done" as="xs:string*"/>
    <xsl:param name="roots" as="xs:string*"/>
    <xsl:variable name="next" as="xs:string?" select="head($todo)"/>
    <xsl:sequence select="
        if (empty($next)) then ()
        else if ($next = $done) then fp:gather(tail($todo), $done, $roots)
        else ($next, fp:gather((tail($todo), fp:file-refs(doc($next), $roots)), ($done, $next), $roots))"/>
  </xsl:function>

  <!-- "components/Arm.compdef.uml": $uri relative to the folder of $base -->
  <xsl:function name="fp:relative-uri" as="xs:string">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:param name="base" as="xs:string"/>
    <xsl:variable name="from" as="xs:string*" select="tokenize(replace($base, '/[^/]*$', '/'), '/')[. ne '']"/>
    <xsl:variable name="to" as="xs:string*" select="tokenize($uri, '/')[. ne '']"/>
    <xsl:variable name="same" as="xs:integer"
        select="(for $i in 1 to min((count($from), count($to) - 1)) return $i[$from[$i] ne $to[$i]], min((count($from), count($to) - 1)) + 1)[1] - 1"/>
    <xsl:sequence select="string-join(((($same + 1) to count($from)) ! '..', subsequence($to, $same + 1)), '/')"/>
  </xsl:function>

  <!-- ================================================ one document -->
  <!-- $norm (the normalised model file) with the normalised linked files
       $linked (in the order of $uris) merged in; $main-uri the model
       file's URI -->
  <xsl:function name="fp:merged" as="document-node()">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="linked" as="document-node()*"/>
    <xsl:param name="uris" as="xs:string+"/>
    <xsl:variable name="model-el" as="element()" select="fp:model-el($norm)"/>
    <xsl:document>
      <x:XMI>
        <xsl:apply-templates select="if ($norm/x:XMI) then $norm/x:XMI/node() else $norm/node()" mode="mp:merge">
          <xsl:with-param name="base" as="xs:string" select="$uris[1]" tunnel="yes"/>
          <xsl:with-param name="uris" as="xs:string+" select="$uris" tunnel="yes"/>
          <xsl:with-param name="model-el" as="element()" select="$model-el" tunnel="yes"/>
          <xsl:with-param name="linked" as="document-node()*" select="$linked" tunnel="yes"/>
        </xsl:apply-templates>
        <!-- the stereotype applications of the linked files -->
        <xsl:for-each select="$linked">
          <xsl:variable name="at" as="xs:integer" select="position() + 1"/>
          <xsl:apply-templates select="x:XMI/*[not(namespace-uri() = ($U, $X))]" mode="mp:merge">
            <xsl:with-param name="base" as="xs:string" select="$uris[$at]" tunnel="yes"/>
            <xsl:with-param name="uris" as="xs:string+" select="$uris" tunnel="yes"/>
          </xsl:apply-templates>
        </xsl:for-each>
      </x:XMI>
    </xsl:document>
  </xsl:function>

  <xsl:mode name="mp:merge" on-no-match="shallow-copy"/>

  <!-- the model element gets the linked files' models as nested packages -->
  <xsl:template match="u:Model | u:Package" mode="mp:merge">
    <xsl:param name="model-el" as="element()?" tunnel="yes"/>
    <xsl:param name="linked" as="document-node()*" tunnel="yes"/>
    <xsl:param name="uris" as="xs:string+" tunnel="yes"/>
    <xsl:copy>
      <xsl:apply-templates select="@* | node()" mode="#current"/>
      <xsl:if test=". is $model-el">
        <xsl:for-each select="$linked">
          <xsl:variable name="at" as="xs:integer" select="position() + 1"/>
          <xsl:variable name="lib" as="element()?" select="fp:model-el(.)"/>
          <packagedElement x:type="{fp:meta($lib)}" x:file="{fp:relative-uri($uris[$at], $uris[1])}">
            <xsl:apply-templates select="$lib/@* | $lib/node()" mode="#current">
              <xsl:with-param name="base" as="xs:string" select="$uris[$at]" tunnel="yes"/>
            </xsl:apply-templates>
          </packagedElement>
        </xsl:for-each>
      </xsl:if>
    </xsl:copy>
  </xsl:template>

  <!-- a reference into a loaded file is a reference inside the document -->
  <xsl:template match="@href" mode="mp:merge">
    <xsl:param name="base" as="xs:string" tunnel="yes"/>
    <xsl:param name="uris" as="xs:string+" tunnel="yes"/>
    <xsl:variable name="doc" as="xs:string?" select="fp:model-file-ref(.)"/>
    <xsl:choose>
      <xsl:when test="exists($doc) and string(resolve-uri($doc, $base)) = $uris and contains(., '#')">
        <xsl:attribute name="x:idref" select="substring-after(., '#')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:copy/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>
</xsl:stylesheet>
