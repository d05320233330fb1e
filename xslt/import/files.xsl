<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/files.xsl - models split over several files: find the files a
  model references, load each once, and merge them into one normalised
  document that the rest of the import reads as if it were one file.

  Reads:   the XMI document (the model file) and, through doc(), the model
           files its hrefs name ("../components/Arm.compdef.uml#_id",
           "platform:/resource/Lib/types.uml#_id"), and theirs, each once
           (cycles are fine); through unparsed-text-available(), the
           project markers of the folders above the model (fp:sandbox).
  Writes:  fp:linked-files: the URIs of those files; fp:merged: the
           normalised model file with every linked file's model root as a
           nested package (x:type Model, x:file its URI relative to the
           model file) and every linked file's stereotype applications
           beside the model's own (with x:file), hrefs into loaded files
           turned into x:idref (so references across files resolve through
           the keys like references inside one).
  Params:  none (fp:sandbox takes import.xsl's model-path).

  The sandbox (fp:sandbox; src/robomda/sandbox.py keeps the same rules for
  batch, watch and diagnostics): a model may read the files in
  - the model's folder and the folders of the model path;
  - the model's project: the nearest folder at or above the model's folder
    that holds a project marker ($project-markers: an Eclipse .project, a
    git, Mercurial or Subversion root), found with unparsed-text-available,
    so the same in every engine, from the driver or not; without one, the
    model's folder alone;
  - the other projects of its workspace (the folder holding the project's
    folder): a folder there that holds a marker itself.
  platform:/resource/<Project>/<path> names <path> in the workspace's
  project <Project> (else in a model-path folder holding <Project> or named
  so). Never anything else, never the network.

  Which hrefs name a file to load: a relative, file: or platform:/resource/
  URI with a document part (URL-decoded: "My%20Model.uml" and "My
  Model.uml" are one file), outside a profile application, that is not a
  library the import knows (fp:href-library; pathmap://, platform:/plugin/
  and the like), not a profile (*.profile.uml / *.profile.xmi: stereotypes
  are read from their applications) and not a MagicDraw used project
  (fp:used-project: PROJECT-<id>?resource=..., *.mdzip; robomda cannot read
  those). Any other scheme stays an external reference, as before. A
  fragment "#id?Path/Name?" (IBM RSA / RTist) names the element id; the
  part after "?" is its readable path (fp:href-name).

  Ids are per file (EMF: "file#id" is the identity): an xmi:id that several
  files of the model use gets, on every element that carries it, x:qid
  "FILE#id" (FILE: the file's x:file, the model file's own name for it),
  which the keys and fp:id, fp:ref-id of xmi-common.xsl read: a reference
  is resolved in its own file, and the PIM id of such an element is its
  x:qid.
  Errors:  IMP040 a file outside the sandbox; every one of the model is
           reported (f:fail-all); ID is the referencing element's xmi:id.
  Errors (as maps, raised with the others): IMP050 a referenced model file
           that is there but not well-formed XML.
  Warnings: IMP041 a referenced file that is not there (its elements are
           left out; the references stay external, as for a library).
           IMP049 references into a MagicDraw used project that leave out
           something drawn in the model (a type that is not a primitive, a
           general, a port's interface ...): one per used project, on the
           first such reference.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
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

  <!-- the distinct documents $hrefs name (fp:href-doc), each distinct href
       cut once: a model repeats the same library hrefs thousands of times -->
  <xsl:function name="fp:href-docs" as="xs:string*">
    <xsl:param name="hrefs" as="attribute()*"/>
    <xsl:sequence select="distinct-values(distinct-values($hrefs) ! fp:href-doc(.))"/>
  </xsl:function>

  <!-- the id an href's fragment names: before "?" (RSA "#id?Path/Name?") -->
  <xsl:function name="fp:href-id" as="xs:string">
    <xsl:param name="href" as="xs:string"/>
    <xsl:sequence select="substring-before(substring-after($href, '#') || '?', '?')"/>
  </xsl:function>

  <!-- the MagicDraw used project an href's document part names
       ("PROJECT-<id>" of "local:/PROJECT-<id>?resource=...", "Lib.mdzip"),
       else () -->
  <xsl:function name="fp:used-project" as="xs:string?">
    <xsl:param name="doc" as="xs:string"/>
    <xsl:sequence select="
        if (matches($doc, '(^|[:/])PROJECT-[0-9A-Za-z_\-]+(\?|$)', 'i'))
          then replace($doc, '^(.*[:/])?(PROJECT-[0-9A-Za-z_\-]+).*$', '$2', 'i')
        else if (matches($doc, '\.mdzip$', 'i')) then fp:uri-decode(replace($doc, '^.*/', ''))
        else ()"/>
  </xsl:function>

  <!-- $doc (the document part of an href) when, by the text alone, it may
       name a model file to load (fp:model-file-ref without the place of
       the href), else () -->
  <xsl:function name="fp:model-file-doc" as="xs:string?">
    <xsl:param name="doc" as="xs:string"/>
    <xsl:sequence select="
        if ($doc eq '' or matches($doc, '\.profile\.(uml|xmi)$', 'i')) then ()
        else if (exists(fp:used-project($doc))) then ()
        else if (fp:href-library($doc) ne 'external') then ()
        else if (matches($doc, '^platform:/resource/[^/]+/.', 'i')) then $doc
        else if (matches($doc, '^[A-Za-z][A-Za-z0-9+.\-]*:') and not(starts-with(lower-case($doc), 'file:'))) then ()
        else $doc"/>
  </xsl:function>

  <!-- a file URI in one spelling (file:/a, file:///a: engines differ) -->
  <xsl:function name="fp:uri-key" as="xs:string">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="replace($uri, '^file:/+', 'file:/')"/>
  </xsl:function>

  <!-- $uri without "." and ".." steps (resolve-uri may leave those of an
       absolute reference) -->
  <xsl:function name="fp:clean-uri" as="xs:string">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="if (not(matches($uri, '/\.\.?(/|$)'))) then $uri
        else string-join(fp:clean-steps(tokenize($uri, '/'), ()), '/')"/>
  </xsl:function>

  <xsl:function name="fp:clean-steps" as="xs:string*">
    <xsl:param name="todo" as="xs:string*"/>
    <xsl:param name="done" as="xs:string*"/>
    <xsl:variable name="step" as="xs:string?" select="head($todo)"/>
    <xsl:sequence select="
        if (empty($todo)) then $done
        else if ($step eq '.') then fp:clean-steps(tail($todo), $done)
        else if ($step eq '..' and count($done) gt 1 and not($done[last()] = ('', '..')))
          then fp:clean-steps(tail($todo), $done[position() lt last()])
        else fp:clean-steps(tail($todo), ($done, $step))"/>
  </xsl:function>

  <!-- =================================================== the sandbox -->
  <!-- the files whose presence makes a folder a project (files, not
       folders: unparsed-text-available tells them in every engine):
       Eclipse, git (a repository, or a worktree / submodule whose .git is
       a file), Mercurial, Subversion -->
  <xsl:variable name="project-markers" as="xs:string+"
      select="('.project', '.git/HEAD', '.git', '.hg/requires', '.svn/entries')"/>

  <xsl:function name="fp:is-project" as="xs:boolean">
    <xsl:param name="folder" as="xs:string"/>
    <xsl:sequence select="some $marker in $project-markers satisfies unparsed-text-available($folder || $marker)"/>
  </xsl:function>

  <!-- the nearest folder at or above $folder (a URI ending in "/") that is
       a project, if any -->
  <xsl:function name="fp:project" as="xs:string?">
    <xsl:param name="folder" as="xs:string"/>
    <xsl:variable name="up" as="xs:string" select="replace($folder, '[^/]+/$', '')"/>
    <xsl:sequence select="if (fp:is-project($folder)) then $folder
                          else if ($up eq $folder) then () else fp:project($up)"/>
  </xsl:function>

  <!-- the sandbox of the model $doc with the model path $model-path
       (space-separated folder URIs): map { 'folder': the model's folder,
       'path': the model path's folders, 'project': the model's project,
       'workspace': the folder holding it } (see the header) -->
  <xsl:function name="fp:sandbox" as="map(*)">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="model-path" as="xs:string"/>
    <xsl:variable name="folder" as="xs:string" select="string(resolve-uri('.', base-uri($doc)))"/>
    <xsl:variable name="project" as="xs:string?" select="fp:project($folder)"/>
    <xsl:sequence select="map {
        'folder': $folder,
        'path': tokenize($model-path) ! (if (ends-with(., '/')) then . else . || '/'),
        'project': $project,
        'workspace': $project ! replace(., '[^/]+/$', '')[. ne $project] }"/>
  </xsl:function>

  <!-- whether file URI $uri may be read: inside the model's folder, a
       model-path folder, the project, or another project of the workspace;
       IMP040 otherwise -->
  <xsl:function name="fp:in-sandbox" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:variable name="key" as="xs:string" select="fp:uri-key(fp:clean-uri($uri))"/>
    <xsl:variable name="workspace" as="xs:string?" select="$sandbox?workspace ! fp:uri-key(.)"/>
    <xsl:variable name="step" as="xs:string"
        select="if (exists($workspace) and starts-with($key, $workspace))
                then substring-before(substring-after($key, $workspace), '/') else ''"/>
    <xsl:sequence select="(some $root in ($sandbox?folder, $sandbox?path, $sandbox?project)
                             satisfies starts-with($key, fp:uri-key($root)))
                          or ($step ne '' and fp:is-project($workspace || $step || '/'))"/>
  </xsl:function>

  <!-- the sandbox in words, for IMP040 -->
  <xsl:function name="fp:sandbox-text" as="xs:string">
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:sequence select="
        if (exists($sandbox?project))
        then 'the model''s project (' || fp:uri-decode($sandbox?project) || ', the nearest folder above the model '
             || 'with a .project, .git, .hg or .svn), the other projects of its workspace ('
             || ($sandbox?workspace ! fp:uri-decode(.), '-')[1] || ') and the model path'
        else 'the model''s folder (no folder above it is a project: none holds a .project, .git, .hg or .svn) '
             || 'and the model path'"/>
  </xsl:function>

  <!-- the absolute URI the document part $doc of an href written in the
       file $base names (fp:model-file-doc said it may name a file), '' for
       a platform:/resource/ URI with no workspace or model path to look in -->
  <xsl:function name="fp:ref-uri" as="xs:string">
    <xsl:param name="doc" as="xs:string"/>
    <xsl:param name="base" as="xs:string"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:choose>
      <xsl:when test="matches($doc, '^platform:/resource/', 'i')">
        <xsl:variable name="project" as="xs:string" select="replace($doc, '^platform:/resource/([^/]+)/.*$', '$1', 'i')"/>
        <xsl:variable name="rest" as="xs:string" select="iri-to-uri(replace($doc, '^platform:/resource/[^/]+/', '', 'i'))"/>
        <xsl:variable name="candidates" as="xs:string*" select="
            (($sandbox?workspace, $sandbox?path) ! (. || iri-to-uri($project) || '/' || $rest),
             $sandbox?path[ends-with(fp:uri-decode(.), '/' || fp:uri-decode($project) || '/')] ! (. || $rest))
            ! fp:clean-uri(.)"/>
        <xsl:sequence select="($candidates[doc-available(.)], $candidates, '')[1]"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="fp:clean-uri(string(resolve-uri(iri-to-uri($doc), $base)))"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- the element whose reference $href is, for messages: the nearest
       element with an xmi:id -->
  <xsl:function name="fp:referrer" as="element()?">
    <xsl:param name="href" as="attribute()"/>
    <xsl:sequence select="$href/ancestor::*[@*[local-name() eq 'id'][fp:is-xmi-ns(namespace-uri())]][1]"/>
  </xsl:function>

  <!-- the absolute URIs of the model files $doc references directly, each
       checked against the sandbox (an IMP040 map for f:fail-all where it
       is outside) and for existence (IMP041) -->
  <xsl:function name="fp:file-refs" as="item()*">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <!-- the few distinct document parts are tested first: the many hrefs
         into libraries (pathmap://...) are then passed over without a
         call each -->
    <xsl:variable name="hrefs" as="attribute()*" select="$doc//@href"/>
    <xsl:variable name="files" as="xs:string*"
        select="fp:href-docs($hrefs)[exists(fp:model-file-doc(.))]"/>
    <xsl:variable name="base" as="xs:string" select="string(base-uri($doc))"/>
    <xsl:for-each-group select="if (empty($files)) then () else $hrefs[fp:href-doc(.) = $files][fp:model-file-ref(.)]"
                        group-by="(fp:ref-uri(fp:model-file-ref(.), $base, $sandbox)[. ne ''], fp:model-file-ref(.))[1]">
      <!-- '' for a platform:/resource/ URI found nowhere (grouped by itself) -->
      <xsl:variable name="uri" as="xs:string" select="fp:ref-uri(fp:model-file-ref(.), $base, $sandbox)"/>
      <xsl:variable name="who" as="element()?" select="fp:referrer(.)"/>
      <xsl:variable name="id" as="xs:string" select="string($who/@*[local-name() eq 'id'][fp:is-xmi-ns(namespace-uri())])"/>
      <xsl:variable name="what" as="xs:string"
          select="(if ($who) then local-name($who) || ' ' || (($who/@name, '')[1]) else 'an element') || ' refers to ''' || . || ''''"/>
      <xsl:choose>
        <xsl:when test="$uri eq ''">
          <xsl:sequence select="map { 'code': 'IMP040', 'id': $id, 'message': $what || ', a file of the Eclipse project '''
              || fp:uri-decode(replace(., '^platform:/resource/([^/]+)/.*$', '$1', 'i')) || ''', but no folder above the '
              || 'model is a project (none holds a .project, .git, .hg or .svn), so robomda knows no workspace to find it in: '
              || 'keep the model in its project, or add that project''s folder (or the folder holding it) with --model-path DIR' }"/>
        </xsl:when>
        <xsl:when test="not(fp:in-sandbox($uri, $sandbox))">
          <xsl:sequence select="map { 'code': 'IMP040', 'id': $id, 'message': $what || ', a file outside '
              || fp:sandbox-text($sandbox) || ' (' || fp:uri-decode($uri) || '): robomda reads only files there and '
              || 'never the network; add its folder with --model-path DIR' }"/>
        </xsl:when>
        <xsl:when test="not(doc-available($uri)) and unparsed-text-available($uri)">
          <!-- there, but not XML (a file saved half-way): bad input, not a
               file left out -->
          <xsl:sequence select="map { 'code': 'IMP050', 'id': $id, 'message': $what || ', but '
              || fp:uri-decode($uri) || ' is not well-formed XML (saved half-way?): an XML parser names the line'
              || ' (xmllint --noout FILE); robomda reads none of the model until it is' }"/>
        </xsl:when>
        <xsl:when test="not(doc-available($uri))">
          <xsl:sequence select="f:warn('IMP041', $id, $what || ', but ' || fp:uri-decode($uri) || ' is not there (or not XML): '
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
       once, in the order first reached (breadth first); every reference
       outside the sandbox, in any of those files, is reported (IMP040,
       f:fail-all) -->
  <xsl:function name="fp:linked-files" as="xs:string*">
    <xsl:param name="main" as="document-node()"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:variable name="refs" as="item()*" select="fp:file-refs($main, $sandbox)"/>
    <xsl:variable name="found" as="item()*"
        select="$refs[. instance of map(*)],
                fp:gather($refs[. instance of xs:string], string(base-uri($main)), $sandbox)"/>
    <xsl:variable name="refused" as="map(*)*" select="$found[. instance of map(*)]"/>
    <xsl:sequence select="if (exists($refused)) then f:fail-all($refused) else $found[. instance of xs:string]"/>
  </xsl:function>

  <!-- the files of $todo not $done and those they reach, with the refusals
       (IMP040 maps) met on the way -->
  <xsl:function name="fp:gather" as="item()*">
    <xsl:param name="todo" as="xs:string*"/>
    <xsl:param name="done" as="xs:string*"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:variable name="next" as="xs:string?" select="head($todo)"/>
    <xsl:variable name="refs" as="item()*"
        select="if (empty($next) or $next = $done) then () else fp:file-refs(doc($next), $sandbox)"/>
    <xsl:sequence select="
        if (empty($next)) then ()
        else if ($next = $done) then fp:gather(tail($todo), $done, $sandbox)
        else ($next, $refs[. instance of map(*)],
              fp:gather((tail($todo), $refs[. instance of xs:string]), ($done, $next), $sandbox))"/>
  </xsl:function>

  <!-- ======================================== MagicDraw used projects -->
  <!-- IMP049: one warning per MagicDraw used project that references of
       the merged document $norm lead into, where something drawn is left
       out (fp:leaves-out) -->
  <xsl:function name="fp:used-project-warnings" as="empty-sequence()">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:variable name="hrefs" as="attribute()*" select="$norm//@href"/>
    <xsl:variable name="docs" as="xs:string*"
        select="fp:href-docs($hrefs)[exists(fp:used-project(.))][fp:href-library(.) eq 'external']"/>
    <xsl:for-each-group select="if (empty($docs)) then () else $hrefs[fp:href-doc(.) = $docs][fp:leaves-out(.)]"
                        group-by="fp:used-project(fp:href-doc(.))">
      <xsl:variable name="who" as="element()?" select="ancestor::*[@x:id][1]"/>
      <xsl:variable name="names" as="xs:string*"
          select="distinct-values(current-group() ! (local-name(..) || ' ''' || fp:href-name(., ..) || ''''))"/>
      <xsl:sequence select="f:warn('IMP049', if ($who) then fp:id($who) else '',
          (if ($who) then fp:label($who) else 'an element') || ' refers into the MagicDraw used project '''
          || current-grouping-key() || ''' (' || string(.) || '), which robomda cannot read: '
          || count(current-group()) || ' reference(s) into it (' || string-join(subsequence($names, 1, 5), ', ')
          || (if (count($names) gt 5) then ', ...' else '') || ') are read as external references, like a '
          || 'library''s, and what they name is not imported; export the used project''s elements into the model '
          || '(or as XMI beside it) to have them generated')"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- whether the reference $href into a used project leaves out something
       drawn in the model: not when it is a package, element or profile
       import, nor a type whose name is a primitive -->
  <xsl:function name="fp:leaves-out" as="xs:boolean">
    <xsl:param name="href" as="attribute()"/>
    <xsl:sequence select="
        not($href/ancestor::*[local-name() = ('profileApplication', 'appliedProfile', 'packageImport', 'elementImport')])
        and not(local-name($href/..) eq 'type'
                and exists(fp:primitive-kind('external', fp:href-name($href, $href/..))))"/>
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
       $linked (in the order of $uris) merged in; $uris the model file's
       URI, then those of the linked files -->
  <xsl:function name="fp:merged" as="document-node()">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="linked" as="document-node()*"/>
    <xsl:param name="uris" as="xs:string+"/>
    <xsl:param name="sandbox" as="map(*)"/>
    <xsl:variable name="model-el" as="element()" select="fp:model-el($norm)"/>
    <xsl:variable name="files" as="xs:string+" select="$uris ! fp:relative-uri(., $uris[1])"/>
    <!-- the ids that more than one file uses -->
    <xsl:variable name="shared" as="map(xs:string, xs:boolean)">
      <xsl:map>
        <xsl:for-each-group select="($norm, $linked) ! distinct-values(.//@x:id ! string(.))" group-by=".">
          <xsl:if test="count(current-group()) gt 1">
            <xsl:map-entry key="current-grouping-key()" select="true()"/>
          </xsl:if>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:document>
      <x:XMI x:file="{$files[1]}">
        <xsl:apply-templates select="if ($norm/x:XMI) then $norm/x:XMI/node() else $norm/node()" mode="mp:merge">
          <xsl:with-param name="base" as="xs:string" select="$uris[1]" tunnel="yes"/>
          <xsl:with-param name="file" as="xs:string" select="$files[1]" tunnel="yes"/>
          <xsl:with-param name="uris" as="xs:string+" select="$uris" tunnel="yes"/>
          <xsl:with-param name="files" as="xs:string+" select="$files" tunnel="yes"/>
          <xsl:with-param name="shared" as="map(xs:string, xs:boolean)" select="$shared" tunnel="yes"/>
          <xsl:with-param name="sandbox" as="map(*)" select="$sandbox" tunnel="yes"/>
          <xsl:with-param name="model-el" as="element()" select="$model-el" tunnel="yes"/>
          <xsl:with-param name="linked" as="document-node()*" select="$linked" tunnel="yes"/>
        </xsl:apply-templates>
        <!-- the stereotype applications of the linked files -->
        <xsl:for-each select="$linked">
          <xsl:variable name="at" as="xs:integer" select="position() + 1"/>
          <xsl:apply-templates select="x:XMI/*[not(namespace-uri() = ($U, $X))]" mode="mp:merge">
            <xsl:with-param name="base" as="xs:string" select="$uris[$at]" tunnel="yes"/>
            <xsl:with-param name="file" as="xs:string" select="$files[$at]" tunnel="yes"/>
            <xsl:with-param name="uris" as="xs:string+" select="$uris" tunnel="yes"/>
            <xsl:with-param name="files" as="xs:string+" select="$files" tunnel="yes"/>
            <xsl:with-param name="shared" as="map(xs:string, xs:boolean)" select="$shared" tunnel="yes"/>
            <xsl:with-param name="sandbox" as="map(*)" select="$sandbox" tunnel="yes"/>
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
    <xsl:param name="files" as="xs:string+" tunnel="yes"/>
    <xsl:copy>
      <xsl:apply-templates select="@* | node()" mode="#current"/>
      <xsl:if test=". is $model-el">
        <xsl:for-each select="$linked">
          <xsl:variable name="at" as="xs:integer" select="position() + 1"/>
          <xsl:variable name="lib" as="element()?" select="fp:model-el(.)"/>
          <packagedElement x:type="{fp:meta($lib)}" x:file="{$files[$at]}">
            <xsl:apply-templates select="$lib/@* | $lib/node()" mode="#current">
              <xsl:with-param name="base" as="xs:string" select="$uris[$at]" tunnel="yes"/>
              <xsl:with-param name="file" as="xs:string" select="$files[$at]" tunnel="yes"/>
            </xsl:apply-templates>
          </packagedElement>
        </xsl:for-each>
      </xsl:if>
    </xsl:copy>
  </xsl:template>

  <!-- a stereotype application of a linked file says which file it is of -->
  <xsl:template match="/x:XMI/*[not(namespace-uri() = ($U, $X))]" mode="mp:merge">
    <xsl:param name="file" as="xs:string" tunnel="yes"/>
    <xsl:copy>
      <xsl:attribute name="x:file" select="$file"/>
      <xsl:apply-templates select="@* | node()" mode="#current"/>
    </xsl:copy>
  </xsl:template>

  <!-- an id that several files use is qualified by its file (x:qid) -->
  <xsl:template match="@x:id" mode="mp:merge">
    <xsl:param name="file" as="xs:string" tunnel="yes"/>
    <xsl:param name="shared" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:copy/>
    <xsl:if test="map:contains($shared, string(.))">
      <xsl:attribute name="x:qid" select="$file || '#' || ."/>
    </xsl:if>
  </xsl:template>

  <!-- a reference into a loaded file is a reference inside the document:
       the id of its fragment (before an RSA "?Path?"), qualified by the
       file when several files use it -->
  <xsl:template match="@href" mode="mp:merge">
    <xsl:param name="base" as="xs:string" tunnel="yes"/>
    <xsl:param name="uris" as="xs:string+" tunnel="yes"/>
    <xsl:param name="files" as="xs:string+" tunnel="yes"/>
    <xsl:param name="shared" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:param name="sandbox" as="map(*)" tunnel="yes"/>
    <xsl:variable name="doc" as="xs:string?" select="fp:model-file-ref(.)"/>
    <xsl:variable name="at" as="xs:integer?"
        select="if (exists($doc) and contains(., '#'))
                then index-of($uris ! fp:uri-key(.), fp:uri-key(string(fp:ref-uri($doc, $base, $sandbox))))[1] else ()"/>
    <xsl:variable name="id" as="xs:string" select="fp:href-id(.)"/>
    <xsl:choose>
      <xsl:when test="exists($at) and $id ne ''">
        <xsl:attribute name="x:idref" select="if (map:contains($shared, $id)) then $files[$at] || '#' || $id else $id"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:copy/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>
</xsl:stylesheet>
